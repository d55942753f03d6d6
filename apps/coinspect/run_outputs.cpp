#include "run_outputs.h"

#include <algorithm>
#include <cinttypes>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <system_error>

#include "coinspect/core/error.h"
#include "coinspect/core/version.h"
#include "coinspect/record/run_report.h"
#include "coinspect/record/score_csv.h"
#include "coinspect/world/scenario_source.h"

namespace coinspect::app {

namespace {

std::vector<double> happened(const std::vector<double>& at) {
  std::vector<double> times;
  for (const double t : at)
    if (!std::isnan(t)) times.push_back(t);
  std::sort(times.begin(), times.end());
  return times;
}

record::RunReportFeatures makeFeatures(const sim::MissionSummary& s) {
  const auto& f = s.features;
  record::RunReportFeatures r;
  r.total = f.total;
  r.discovered = f.discovered;
  r.assigned = f.assigned;
  r.inspected = f.inspected;
  r.collected = f.collected;
  r.finishRate = f.finishRate();
  r.finishTime = f.finishTime;
  r.meetings = {{"gcs_explorer", f.meetingsGcsExplorer},
                {"explorer_inspector", f.meetingsExplorerInspector},
                {"other", f.meetingsOther}};
  r.punctuality = {{"on_time", f.promisesOnTime},
                   {"early", f.promisesEarly},
                   {"late", f.promisesLate},
                   {"missed", f.promisesMissed},
                   {"rescheduled", f.promisesRescheduled}};
  r.timeline = {{"discovered", happened(f.discoveredAt)},
                {"assigned", happened(f.assignedAt)},
                {"inspected", happened(f.inspectedAt)},
                {"collected", happened(f.collectedAt)}};
  std::vector<double> priorityCollectedAt;
  for (size_t i = 0; i < f.collectedAt.size() && i < f.highPriority.size(); ++i)
    if (f.highPriority[i]) priorityCollectedAt.push_back(f.collectedAt[i]);
  r.timeline["priority"] = happened(priorityCollectedAt);
  r.priorityTotal = f.priorityTotal;
  r.priorityCollected = f.priorityCollected;
  r.priorityFinishTime = f.priorityFinishTime;
  for (size_t i = 0; i < f.units.size(); ++i) {
    const auto& u = f.units[i];
    record::RunReportFeatureUnit unit;
    unit.name = s.units[i].name;
    for (int a = 0; a < agent::kActivityCount; ++a)
      unit.activitySeconds[agent::toString(static_cast<agent::Activity>(a))] =
          u.activitySeconds[static_cast<size_t>(a)];
    unit.idleSeconds =
        u.activitySeconds[static_cast<size_t>(agent::Activity::TravellingToMeeting)] +
        u.activitySeconds[static_cast<size_t>(agent::Activity::Waiting)];
    unit.detected = u.detected;
    unit.inspected = u.inspected;
    unit.held = u.held;
    r.units.push_back(unit);
  }
  return r;
}

record::RunReport makeReport(const sim::MissionSummary& s, const Config& ini,
                             const std::string& configFile) {
  record::RunReport r;
  r.configFile = configFile;
  for (const auto& section : ini.sections())
    for (const auto& key : ini.keys(section))
      r.config[section][key] = ini.getString(section, key);
  r.scenario = s.scenario;
  r.strategy = s.strategy;
  r.seed = s.seed;
  r.scoring = s.scoring;
  r.score = s.score;
  r.detected = s.detected;
  r.totalPoints = s.totalPoints;
  for (const auto& u : s.units) {
    record::RunReportUnit unit;
    unit.name = u.name;
    unit.role = u.role;
    unit.alive = u.alive;
    unit.deathCause = u.deathCause;
    unit.distanceFlown = u.distanceFlown;
    unit.captures = u.captures;
    unit.detected = u.detected;
    unit.ownScore = u.ownScore;
    unit.rejectedCommands = u.rejectedCommands;
    unit.lowestEnergy = u.lowestEnergy;
    unit.chargedFor = u.chargedFor;
    r.units.push_back(unit);
  }
  r.collisions = s.collisions;
  r.deaths = s.deaths;
  r.messagesSent = s.messagesSent;
  r.messagesDelivered = s.messagesDelivered;
  r.messagesDropped = s.messagesDropped;
  r.keyFrames = s.keyFrames;
  r.keyFramesDelivered = s.keyFramesDelivered;
  r.started = s.started;
  r.startTime = s.startTime;
  r.missionTime = s.missionTime;
  r.budget = s.budget;
  r.simTime = s.simTime;
  r.runMode = s.runMode;
  r.realtimeFactor = s.requestedRealtimeFactor;
  if (s.features.enabled) r.features = makeFeatures(s);
  r.timing.decisions = s.decisionTimes.count;
  r.timing.threads = s.threads;
  r.timing.decisionTimeMean = s.decisionTimes.mean();
  r.timing.decisionTimeMax = s.decisionTimes.max;
  r.timing.decisionTimeP50 = s.decisionTimes.quantile(0.5);
  r.timing.decisionTimeP95 = s.decisionTimes.quantile(0.95);
  r.timing.wallTime = s.wallTime;
  r.timing.realTimeFactor = s.realTimeFactor();
  r.timing.stages = {{"physics", s.stages.physics}, {"decisions", s.stages.decisions},
                     {"lidar", s.stages.lidar},     {"topology", s.stages.topology},
                     {"scoring", s.stages.scoring}, {"collisions", s.stages.collisions},
                     {"pacing", s.stages.pacing}};
  return r;
}

}  // namespace

record::RunHeader makeRunHeader(const sim::Mission& mission, const Config& ini,
                                const std::filesystem::path& runFolder) {
  record::RunHeader header;
  header.coinspectVersion = coinspect::version();
  header.seed = mission.config().seed;
  char hash[17];
  std::snprintf(hash, sizeof hash, "%016" PRIx64, mission.scenario().contentHash());
  header.scenarioHash = hash;
  header.configIni = ini.toText();
  // The recorded config is read back with the rawlog's folder as its own (openRecordedRun): a
  // relative path written for the INI's folder (config/caric-mbs.ini's ../../shared/...) is
  // recorded relative to the run folder instead. Generator names and absolute paths stay.
  Config recorded = Config::fromText(header.configIni, ini.source());
  bool rewritten = false;
  for (const char* key : {"scenario", "airframes", "lidars"}) {
    const std::string written = ini.getString("mission", key, "");
    if (written.empty() || !std::filesystem::path(written).is_relative() ||
        (std::string(key) == "scenario" && world::isGeneratorName(written)))
      continue;
    std::error_code error;
    const auto fromRun = std::filesystem::relative(ini.folder() / written, runFolder, error);
    if (error || fromRun.empty()) continue;
    recorded.set("mission", key, fromRun.string());
    rewritten = true;
  }
  if (rewritten) header.configIni = recorded.toText();
  return header;
}

RunOutputs::RunOutputs(sim::Mission& mission, std::filesystem::path folder, const Config& ini)
    : folder_(std::move(folder)) {
  std::error_code error;
  std::filesystem::create_directories(folder_, error);
  if (error)
    throw InputError(folder_.string(), "--out", "cannot create the folder: " + error.message());
  for (const auto& unit : mission.summary().units)
    trajectories_.emplace_back(folder_ / (unit.name + ".tum"));
  mission.setControlTickObserver([this](const sim::Mission& m) {
    for (size_t i = 0; i < trajectories_.size(); ++i) {
      const auto state = m.unitState(i);
      trajectories_[i].append(m.time(), state.position, state.yaw, state.pitch, state.roll);
    }
  });
  if (mission.config().record.rawlog)
    mission.startRecording(folder_ / "run.rawlog", makeRunHeader(mission, ini, folder_));
}

void RunOutputs::finish(const sim::Mission& mission, const Config& ini,
                        const std::string& configFile, const std::string& summaryText) {
  for (auto& trajectory : trajectories_)
    trajectory.close();
  std::ofstream(folder_ / "summary.txt") << summaryText;
  std::ofstream events(folder_ / "events.csv");
  events << "time,kind,unit,detail\n";
  for (const auto& e : mission.events())
    events << e.time << ',' << e.kind << ',' << e.unit << ",\"" << e.detail << "\"\n";
  record::writeCaricScoreCsv(folder_ / "score.csv", mission.scenario().interestPoints,
                             mission.gcsValues());
  record::writeRunReportJson(folder_ / "report.json",
                             makeReport(mission.summary(), ini, configFile));
}

}  // namespace coinspect::app
