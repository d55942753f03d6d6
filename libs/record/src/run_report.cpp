#include "coinspect/record/run_report.h"

#include <fstream>
#include <nlohmann/json.hpp>

#include "coinspect/core/error.h"

namespace coinspect::record {

namespace {

// nlohmann::json objects are std::map based: keys come out sorted, the text is deterministic.
nlohmann::json unitJson(const RunReportUnit& unit) {
  return {{"name", unit.name},
          {"role", unit.role},
          {"alive", unit.alive},
          {"death_cause", unit.deathCause},
          {"distance_flown", unit.distanceFlown},
          {"captures", unit.captures},
          {"detected", unit.detected},
          {"own_score", unit.ownScore},
          {"rejected_commands", unit.rejectedCommands},
          {"energy_lowest",
           unit.lowestEnergy ? nlohmann::json(*unit.lowestEnergy) : nlohmann::json(nullptr)},
          {"charged_s", unit.chargedFor}};
}

nlohmann::json featuresJson(const RunReportFeatures& f) {
  nlohmann::json units = nlohmann::json::array();
  for (const auto& u : f.units)
    units.push_back({{"name", u.name},
                     {"activity_seconds", u.activitySeconds},
                     {"idle_seconds", u.idleSeconds},
                     {"detected", u.detected},
                     {"inspected", u.inspected},
                     {"held", u.held}});
  return {{"total", f.total},
          {"discovered", f.discovered},
          {"assigned", f.assigned},
          {"inspected", f.inspected},
          {"collected", f.collected},
          {"finish_rate", f.finishRate},
          {"finish_time", f.finishTime ? nlohmann::json(*f.finishTime) : nlohmann::json(nullptr)},
          {"meetings", f.meetings},
          {"punctuality", f.punctuality},
          {"timeline", f.timeline},
          {"priority",
           {{"total", f.priorityTotal},
            {"collected", f.priorityCollected},
            {"finish_time", f.priorityFinishTime ? nlohmann::json(*f.priorityFinishTime)
                                                 : nlohmann::json(nullptr)}}},
          {"units", units}};
}

}  // namespace

std::string runReportJson(const RunReport& report) {
  nlohmann::json units = nlohmann::json::array();
  for (const auto& unit : report.units)
    units.push_back(unitJson(unit));
  nlohmann::json json = {
      {"config", {{"file", report.configFile}, {"values", report.config}}},
      {"scenario", report.scenario},
      {"strategy", report.strategy},
      {"seed", report.seed},
      {"scoring", report.scoring},
      {"score", report.score},
      {"detected", report.detected},
      {"total_points", report.totalPoints},
      {"units", units},
      {"collisions", report.collisions},
      {"deaths", report.deaths},
      {"messages",
       {{"sent", report.messagesSent},
        {"delivered", report.messagesDelivered},
        {"dropped", report.messagesDropped},
        {"key_frames", report.keyFrames},
        {"key_frames_delivered", report.keyFramesDelivered}}},
      {"clock",
       {{"started", report.started},
        {"start_time", report.startTime},
        {"mission_time", report.missionTime},
        {"budget", report.budget},
        {"sim_time", report.simTime}}},
      {"run_mode", {{"mode", report.runMode}, {"realtime_factor", report.realtimeFactor}}},
      {"timing",
       {{"wall_time", report.timing.wallTime},
        {"real_time_factor", report.timing.realTimeFactor},
        {"threads", report.timing.threads},
        {"stages", report.timing.stages},
        {"decisions", report.timing.decisions},
        {"decision_time_mean", report.timing.decisionTimeMean},
        {"decision_time_max", report.timing.decisionTimeMax},
        {"decision_time_p50", report.timing.decisionTimeP50},
        {"decision_time_p95", report.timing.decisionTimeP95}}}};
  if (report.features) json["features"] = featuresJson(*report.features);
  // Strings here come from the user (config values, paths): a byte that is not UTF-8 is written
  // as U+FFFD instead of throwing and losing the report at the end of a mission.
  return json.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) + "\n";
}

void writeRunReportJson(const std::filesystem::path& path, const RunReport& report) {
  const std::string text = runReportJson(report);
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  if (!out) throw InputError(path.string(), "open", "cannot write the file");
  out << text;
  out.flush();
  if (!out) throw InputError(path.string(), "write", "writing the file failed");
}

}  // namespace coinspect::record
