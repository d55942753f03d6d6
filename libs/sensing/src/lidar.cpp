#include "coinspect/sensing/lidar.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "coinspect/core/error.h"

namespace coinspect::sensing {

LidarSimulator::LidarSimulator(const LidarSpec& spec, uint64_t seed) : spec_(spec), rng_(seed) {
  COINSPECT_ASSERT(spec.channels >= 1 && spec.columns >= 1);
  directions_.reserve(static_cast<size_t>(spec.rayCount()));
  // Column-major like a spinning head: all channels of one azimuth, then the next azimuth.
  for (int column = 0; column < spec.columns; ++column) {
    const double azimuth = spec.columnAzimuth(column);
    for (int channel = 0; channel < spec.channels; ++channel) {
      const double elevation = spec.channelElevation(channel);
      directions_.emplace_back(std::cos(elevation) * std::cos(azimuth),
                               std::cos(elevation) * std::sin(azimuth), std::sin(elevation));
    }
  }
}

double raySphereDistance(const Eigen::Vector3d& origin, const Eigen::Vector3d& unitDirection,
                         const SphereOccluder& sphere) {
  return RaysFromOrigin(origin, sphere).distance(unitDirection);
}

void LidarSimulator::sweep(const world::RayCaster& caster,
                           const Eigen::Isometry3d& sensorPoseInWorld, LidarScan& out,
                           const std::vector<SphereOccluder>& occluders) {
  const size_t n = directions_.size();
  const Eigen::Matrix3d rotation = sensorPoseInWorld.linear();
  const Eigen::Vector3d origin = sensorPoseInWorld.translation();
  origins_.assign(n, origin);
  worldDirections_.resize(n);
  for (size_t i = 0; i < n; ++i)
    worldDirections_[i] = rotation * directions_[i];
  // Nothing beyond maxRange can be a return, so Embree may stop there.
  caster.closestHits(origins_, worldDirections_, spec_.maxRange, distances_);
  for (const auto& sphere : occluders) {
    const RaysFromOrigin rays(origin, sphere);
    if (rays.seesThrough()) continue;  // every ray misses it
    for (size_t i = 0; i < n; ++i)
      distances_[i] = std::min(distances_[i], rays.distance(worldDirections_[i]));
  }

  out.sensorPose = sensorPoseInWorld;
  out.points.clear();
  const bool noisy = spec_.rangeNoiseSigma > 0.0;
  const auto inBand = [&](double r) { return spec_.minRange < r && r < spec_.maxRange; };
  for (size_t i = 0; i < n; ++i) {
    double r = distances_[i];
    if (!inBand(r)) continue;
    if (noisy) {
      r += rng_.normal(0.0, spec_.rangeNoiseSigma);
      if (!inBand(r)) continue;
    }
    out.points.push_back((r * directions_[i]).cast<float>());
  }
}

void LidarSimulator::sweepFromBody(const world::RayCaster& caster, double time,
                                   const Eigen::Isometry3d& bodyPoseInWorld, LidarScan& out,
                                   const std::vector<SphereOccluder>& occluders) {
  out.time = time;
  out.sensorPoseInBody = lidarPoseInBody(spec_, time);
  sweep(caster, bodyPoseInWorld * out.sensorPoseInBody, out, occluders);
}

}  // namespace coinspect::sensing
