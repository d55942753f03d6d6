// The feature timeline of a run's report.json (written by `coinspect run --out`, doc/features.md),
// read for `coinspect plot-features`.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace coinspect::app {

// The stages of features.timeline, in the order features go through them.
const std::vector<std::string>& featureStages();

struct FeatureRunReport {
  std::filesystem::path file;  // the report.json read
  std::string folder;          // the name of the run's folder (the report's)
  std::string strategy;        // "strategy", else config.values.strategy.name, else empty
  std::string scenario;        // "scenario", else empty
  std::vector<double> times;   // features.timeline.<stage>, ascending
  uint64_t total = 0;          // features.total
  double budget = 0.0;         // clock.budget (s)
};

// `run` is a run folder (its report.json is read) or a report.json itself. Throws InputError
// naming the file, and the key when one is missing or bad: features.timeline (a CARIC mission has
// none), features.timeline.<stage> (its times must be finite and >= 0), features.total,
// clock.budget (> 0).
FeatureRunReport readFeatureRunReport(const std::filesystem::path& run, const std::string& stage);

}  // namespace coinspect::app
