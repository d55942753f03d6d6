#include "coinspect/sensing/feature_detection.h"

#include <cmath>

#include "coinspect/core/error.h"

namespace coinspect::sensing {

namespace {

double wrapAngle(double a) {
  return std::remainder(a, 2.0 * M_PI);
}

}  // namespace

void detectFeatures(const FeatureSensor& sensor, const world::Vec3& position, double yaw,
                    const world::InterestPointSet& features, const world::RayCaster& caster,
                    std::vector<uint32_t>& found) {
  found.clear();
  std::vector<uint32_t> near;
  features.withinRadius(position, sensor.range, near);
  for (const uint32_t i : near) {
    const auto& feature = features[i];
    const world::Vec3 d = feature.position - position;
    const double horizontal = std::hypot(d.x(), d.y());
    if (horizontal < 1e-9 && std::abs(d.z()) < 1e-9) continue;  // the sensor sits on it
    if (std::abs(std::atan2(d.z(), horizontal)) > sensor.halfElevation) continue;
    if (horizontal > 1e-9 && std::abs(wrapAngle(std::atan2(d.y(), d.x()) - yaw)) > sensor.halfYaw)
      continue;
    if (sensor.lineOfSight) {
      if (feature.normal.dot(-d) <= 0.0) continue;  // seen from behind its surface
      if (!caster.segmentClear(position, feature.position, kFeatureLineOfSightTolerance)) continue;
    }
    found.push_back(i);
  }
}

InspectionTimer::InspectionTimer(size_t featureCount, double duration)
    : duration_(duration),
      lastCapture_(featureCount, 0),
      runStart_(featureCount, 0.0),
      done_(featureCount, 0) {
  if (!(duration >= 0.0) || !std::isfinite(duration))
    throw InputError("inspection", "duration", "must be a finite time >= 0 s");
}

void InspectionTimer::capture(double time, const std::vector<uint32_t>& counted,
                              std::vector<uint32_t>& completed) {
  ++captureCount_;
  for (const uint32_t f : counted) {
    COINSPECT_ASSERT(f < done_.size());
    if (lastCapture_[f] != captureCount_ - 1 || lastCapture_[f] == 0) runStart_[f] = time;
    lastCapture_[f] = captureCount_;
    // 1 us of slack: capture times are sums of fixed steps.
    if (!done_[f] && time - runStart_[f] >= duration_ - 1e-6) {
      done_[f] = 1;
      completed.push_back(f);
    }
  }
}

}  // namespace coinspect::sensing
