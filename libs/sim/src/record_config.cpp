#include "coinspect/sim/record_config.h"

#include <cmath>

#include "coinspect/core/error.h"

namespace coinspect::sim {

namespace {

record::LidarRecording parseLidarRecording(const Config& config, const std::string& text) {
  if (text == "keyframes") return record::LidarRecording::KeyFrames;
  if (text == "all") return record::LidarRecording::All;
  if (text == "none") return record::LidarRecording::None;
  throw InputError(config.source(), "[record] lidar",
                   "'" + text + "' is not a LiDAR recording mode (keyframes, all or none)");
}

}  // namespace

RecordConfig RecordConfig::read(const Config& config, double physicsStep) {
  const std::string r = "record";
  RecordConfig out;
  out.rawlog = config.getBool(r, "rawlog", out.rawlog);
  auto& options = out.options;
  options.groundTruthRate = config.getDouble(r, "ground_truth_rate", options.groundTruthRate);
  // Ground truth is sampled at ticks: more than one sample per physics step cannot exist.
  const double maxRate = 1.0 / physicsStep;
  if (!(options.groundTruthRate > 0.0) || options.groundTruthRate > maxRate * (1.0 + 1e-9))
    throw InputError(
        config.source(), "[record] ground_truth_rate",
        "must be > 0 and at most 1 / physics_step = " + std::to_string(maxRate) + " Hz");
  options.lidar = parseLidarRecording(config, config.getString(r, "lidar", "keyframes"));
  options.flushPeriod = config.getDouble(r, "flush_period", options.flushPeriod);
  if (!(options.flushPeriod > 0.0) || !std::isfinite(options.flushPeriod))
    throw InputError(config.source(), "[record] flush_period",
                     "must be a positive number of seconds");
  return out;
}

}  // namespace coinspect::sim
