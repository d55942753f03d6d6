#include "eval_report.h"

#include <array>
#include <fstream>
#include <nlohmann/json.hpp>

#include "coinspect/core/error.h"

namespace coinspect::app {

namespace {

void printHistogramRow(std::FILE* out, const char* term, const std::string& who,
                       const std::array<uint64_t, eval::kQualityBins>& bins) {
  std::fprintf(out, "%-7s %-12s", term, who.c_str());
  for (const uint64_t count : bins)
    std::fprintf(out, " %8llu", static_cast<unsigned long long>(count));
  std::fputc('\n', out);
}

// Coverage over time on the terminal: Q and detected points at each tenth of the run (the last
// improving merge at or before it). Every merge is in coverage.csv with --out.
void printCoverage(std::FILE* out, const eval::RunEvaluation& r) {
  constexpr int kTenths = 10;
  std::array<double, kTenths> score{};
  std::array<size_t, kTenths> detected{};
  size_t next = 0;
  for (int k = 0; k < kTenths; ++k) {
    const double t = r.endTime * (k + 1) / kTenths;
    // The last tenth takes every merge: t * 10 / 10 may round below the end time.
    while (next < r.coverage.size() && (k + 1 == kTenths || r.coverage[next].time <= t))
      ++next;
    if (next > 0) {
      score[k] = r.coverage[next - 1].score;
      detected[k] = r.coverage[next - 1].detected;
    }
  }
  std::fprintf(out,
               "\ncoverage at each tenth of the run (with --out, coverage.csv has every merge)\n");
  std::fprintf(out, "%-9s", "t s");
  for (int k = 0; k < kTenths; ++k)
    std::fprintf(out, " %9.1f", r.endTime * (k + 1) / kTenths);
  std::fprintf(out, "\n%-9s", "Q");
  for (const double q : score)
    std::fprintf(out, " %9.3f", q);
  std::fprintf(out, "\n%-9s", "detected");
  for (const size_t d : detected)
    std::fprintf(out, " %9zu", d);
  std::fputc('\n', out);
}

nlohmann::json histogramJson(const eval::QualityHistogram& h) {
  return {{"q_blur", h.qBlur}, {"q_res", h.qRes}, {"samples", h.samples()}};
}

std::ofstream openOutput(const std::filesystem::path& path) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  if (!out) throw InputError(path.string(), "open", "cannot write the file");
  return out;
}

void closeOutput(std::ofstream& out, const std::filesystem::path& path) {
  out.close();
  if (!out) throw InputError(path.string(), "write", "writing the file failed");
}

}  // namespace

void printEvaluation(std::FILE* out, const RecordedRun& run, const eval::RunEvaluation& r,
                     const EvalTiming& timing) {
  std::fprintf(out, "rawlog     %s: scenario %s, %s scoring, seed %llu, %zu interest points\n",
               run.rawlog.string().c_str(), run.scenario.name.c_str(), r.scoring.c_str(),
               static_cast<unsigned long long>(run.header.seed), r.pointCount);
  if (r.read.clean)
    std::fprintf(out, "read       %llu objects to t = %.2f s%s\n",
                 static_cast<unsigned long long>(r.read.objects), r.endTime,
                 r.missionEnded ? ", mission ended" : ", no mission end recorded");
  else
    std::fprintf(out, "read       %llu objects to t = %.2f s, then DAMAGED at byte offset %llu\n",
                 static_cast<unsigned long long>(r.read.objects), r.endTime,
                 static_cast<unsigned long long>(r.read.offset));
  std::fprintf(out, "recorded   Q = %.6f, detected %zu / %zu (%llu tally updates)\n",
               r.recordedScore, r.recordedDetected, r.pointCount,
               static_cast<unsigned long long>(r.tallyRecords));
  std::fprintf(out, "re-scored  Q = %.6f, detected %zu / %zu: ", r.score, r.detected, r.pointCount);
  if (r.equal())
    std::fprintf(out, "equal\n");
  else
    std::fprintf(out, "DIFFERENT (%zu point values, %llu tally updates differ)\n",
                 r.valueMismatches, static_cast<unsigned long long>(r.tallyRecordMismatches));
  std::fprintf(out,
               "captures   %llu scored again: %llu seen points in %llu captures differ from "
               "the recorded ones",
               static_cast<unsigned long long>(r.capturesCompared),
               static_cast<unsigned long long>(r.pointMismatches),
               static_cast<unsigned long long>(r.capturesMismatched));
  if (r.capturesNotRescored > 0)
    std::fprintf(out, "; %llu old captures without body state taken as recorded",
                 static_cast<unsigned long long>(r.capturesNotRescored));
  std::fputc('\n', out);
  std::fprintf(out, "speed      %.3f s wall, %.0fx real time\n", timing.wallTime,
               timing.simPerWall());

  printCoverage(out, r);
  std::fprintf(out, "\n%-12s %-12s %9s %9s %10s %9s %8s %9s  %s\n", "unit", "role", "captures",
               "detected", "own Q", "holds GCS", "only it", "LoS s", "state");
  for (const auto& u : r.units) {
    std::fprintf(out, "%-12s %-12s %9llu %9zu %10.3f %9zu %8zu %9.2f  ", u.name.c_str(),
                 world::toString(u.role), static_cast<unsigned long long>(u.captures), u.detected,
                 u.ownScore, u.holdsGcsValue, u.onlyDetector, u.lineOfSightTime);
    if (u.alive)
      std::fprintf(out, "alive");
    else
      std::fprintf(out, "died at %.2f s", u.deathTime);
    if (u.capturesIgnored > 0)
      std::fprintf(out, " (%llu captures after death ignored)",
                   static_cast<unsigned long long>(u.capturesIgnored));
    std::fputc('\n', out);
  }

  std::fprintf(out, "\nseen points per quality bin (0-0.1, 0.1-0.2, ..., 0.9-1)\n");
  for (const bool blur : {true, false}) {
    const char* term = blur ? "q_blur" : "q_res";
    printHistogramRow(out, term, "all", blur ? r.quality.qBlur : r.quality.qRes);
    for (const auto& u : r.units)
      if (u.quality.samples() > 0)
        printHistogramRow(out, "", u.name, blur ? u.quality.qBlur : u.quality.qRes);
  }
}

void writeEvaluationFiles(const std::filesystem::path& folder, const RecordedRun& run,
                          const eval::RunEvaluation& r, const EvalTiming& timing) {
  std::error_code error;
  std::filesystem::create_directories(folder, error);
  if (error)
    throw InputError(folder.string(), "--out", "cannot create the folder: " + error.message());

  nlohmann::json units = nlohmann::json::array();
  for (const auto& u : r.units)
    units.push_back({{"name", u.name},
                     {"role", world::toString(u.role)},
                     {"captures", u.captures},
                     {"captures_ignored", u.capturesIgnored},
                     {"detected", u.detected},
                     {"own_score", u.ownScore},
                     {"holds_gcs_value", u.holdsGcsValue},
                     {"only_detector", u.onlyDetector},
                     {"line_of_sight_time", u.lineOfSightTime},
                     {"alive", u.alive},
                     {"death_time", u.alive ? nlohmann::json() : nlohmann::json(u.deathTime)},
                     {"quality", histogramJson(u.quality)}});
  const nlohmann::json report = {
      {"rawlog", run.rawlog.string()},
      {"scenario", run.scenario.name},
      {"scenario_hash", run.header.scenarioHash},
      {"seed", run.header.seed},
      {"scoring", r.scoring},
      {"total_points", r.pointCount},
      {"read",
       {{"clean", r.read.clean},
        {"objects", r.read.objects},
        {"offset", r.read.offset},
        {"compressed_offset", r.read.compressedOffset},
        {"message", r.read.message}}},
      {"end_time", r.endTime},
      {"mission_ended", r.missionEnded},
      {"recorded",
       {{"score", r.recordedScore}, {"detected", r.recordedDetected}, {"updates", r.tallyRecords}}},
      {"rescored", {{"score", r.score}, {"detected", r.detected}}},
      {"equal", r.equal()},
      {"value_mismatches", r.valueMismatches},
      {"tally_update_mismatches", r.tallyRecordMismatches},
      {"captures",
       {{"compared", r.capturesCompared},
        {"point_mismatches", r.pointMismatches},
        {"mismatched", r.capturesMismatched},
        {"not_rescored", r.capturesNotRescored}}},
      {"coverage_samples", r.coverage.size()},
      {"units", units},
      {"quality", histogramJson(r.quality)},
      {"timing", {{"wall_time", timing.wallTime}, {"real_time_factor", timing.simPerWall()}}}};
  const auto jsonPath = folder / "eval.json";
  auto json = openOutput(jsonPath);
  // The rawlog's path is the user's: a byte that is not UTF-8 is written as U+FFFD (dump would
  // throw and leave eval.json empty).
  json << report.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) << '\n';
  closeOutput(json, jsonPath);

  const auto csvPath = folder / "coverage.csv";
  auto csv = openOutput(csvPath);
  csv << "time,score,detected\n";
  char line[96];
  for (const auto& sample : r.coverage) {
    std::snprintf(line, sizeof line, "%.6f,%.9f,%zu\n", sample.time, sample.score, sample.detected);
    csv << line;
  }
  closeOutput(csv, csvPath);
}

}  // namespace coinspect::app
