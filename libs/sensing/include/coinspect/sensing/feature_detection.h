// SLEI3D features (doc/features.md): an explorer's on-board detector and an inspector's
// inspection timer, both on the scenario's interest points.
//
// The reference code detects a feature within 5 m, +-45 deg of the heading and +-30 deg of
// elevation, ignores occlusion and detects at most one feature per second. Here every feature in
// the field of view is detected at once, only when the line of sight to it is clear and it faces
// the sensor (a detector sees surfaces from the front); `lineOfSight = false` drops both tests, as
// the reference code does (to fly its conditions; the rate cap is not modelled).
#pragma once

#include <cstdint>
#include <vector>

#include "coinspect/world/interest_points.h"
#include "coinspect/world/ray_caster.h"

namespace coinspect::sensing {

struct FeatureSensor {
  double range = 5.0;                         // m, sensor to feature
  double halfYaw = 0.7853981633974483;        // rad, either side of the body heading
  double halfElevation = 0.5235987755982988;  // rad, above and below the horizontal
  bool lineOfSight = true;                    // needs a clear sight line and a facing surface
};

// A segment to a feature counts as clear when its first hit is this close to the feature (the
// feature lies on the surface that ends the ray): the scorer's tolerance (caric-reference.md).
inline constexpr double kFeatureLineOfSightTolerance = 0.025;

// Indices (ascending) of the features that the sensor at `position`, heading `yaw`, detects now.
// Uses `found` as the output (cleared first) so that a caller can keep its buffer.
void detectFeatures(const FeatureSensor& sensor, const world::Vec3& position, double yaw,
                    const world::InterestPointSet& features, const world::RayCaster& caster,
                    std::vector<uint32_t>& found);

// Inspection by keeping a feature in view: a run of consecutive captures of one camera that all
// counted the feature (score >= a threshold) and spans `duration` seconds inspects it. Captures
// must be given in time order; a capture that does not count the feature ends its run.
class InspectionTimer {
 public:
  InspectionTimer(size_t featureCount, double duration);

  // One capture at `time` that counted the features `counted` (any order, no repeats). Appends
  // to `completed` the features whose run reached the duration at this capture (each feature
  // once in the timer's life).
  void capture(double time, const std::vector<uint32_t>& counted, std::vector<uint32_t>& completed);
  bool inspected(uint32_t feature) const { return done_[feature] != 0; }
  double duration() const { return duration_; }

 private:
  double duration_;
  uint64_t captureCount_ = 0;
  std::vector<uint64_t> lastCapture_;  // capture number + 1 that last counted it (0: never)
  std::vector<double> runStart_;       // time of the first capture of its current run
  std::vector<uint8_t> done_;
};

}  // namespace coinspect::sensing
