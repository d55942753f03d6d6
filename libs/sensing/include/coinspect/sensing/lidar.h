// The simulated LiDAR: one instantaneous sweep of all rays of a LidarSpec through the world
// (like the reference's GPU ray sensor, which renders a whole revolution at one instant).
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "coinspect/core/random.h"
#include "coinspect/sensing/lidar_model.h"
#include "coinspect/sensing/sphere_occluder.h"
#include "coinspect/world/ray_caster.h"

namespace coinspect::sensing {

struct LidarScan {
  double time = 0.0;                                                   // simulated s
  Eigen::Isometry3d sensorPose = Eigen::Isometry3d::Identity();        // sensor in the world
  Eigen::Isometry3d sensorPoseInBody = Eigen::Isometry3d::Identity();  // sensor in the body
  std::vector<Eigen::Vector3f> points;  // returns in the SENSOR frame, ray order (column-major)
};

// Copyable; sweeps draw noise from the simulator's own Rng, so each LiDAR owns one simulator.
class LidarSimulator {
 public:
  LidarSimulator(const LidarSpec& spec, uint64_t seed);

  const LidarSpec& spec() const { return spec_; }
  // Unit ray directions in the sensor frame, index = column * channels + channel.
  const std::vector<Eigen::Vector3d>& directions() const { return directions_; }

  // Casts every ray from sensorPoseInWorld; sets out.sensorPose and out.points (returns with
  // minRange < r < maxRange, Gaussian range noise when the spec has some, the noisy range checked
  // again as the reference does). out.time and out.sensorPoseInBody are left to the caller.
  // Rays may also stop at the given spheres.
  void sweep(const world::RayCaster& caster, const Eigen::Isometry3d& sensorPoseInWorld,
             LidarScan& out, const std::vector<SphereOccluder>& occluders = {});

  // The same from the body pose at simulated time t: fills every field of out, with the sensor
  // placed by lidarPoseInBody(spec, t).
  void sweepFromBody(const world::RayCaster& caster, double time,
                     const Eigen::Isometry3d& bodyPoseInWorld, LidarScan& out,
                     const std::vector<SphereOccluder>& occluders = {});

 private:
  LidarSpec spec_;
  Rng rng_;
  std::vector<Eigen::Vector3d> directions_;
  // Per-sweep buffers, kept to avoid allocating during a mission.
  std::vector<world::Vec3> origins_, worldDirections_;
  std::vector<double> distances_;
};

// Distance along the unit direction from origin to the first crossing of the sphere's surface
// (from outside), or +infinity.
double raySphereDistance(const Eigen::Vector3d& origin, const Eigen::Vector3d& unitDirection,
                         const SphereOccluder& sphere);

// raySphereDistance for many rays from one origin: the sphere's terms computed once (a sweep
// tests every ray against every other UAV).
class RaysFromOrigin {
 public:
  RaysFromOrigin(const Eigen::Vector3d& origin, const SphereOccluder& sphere)
      : offset_(origin - sphere.center),
        c_(offset_.squaredNorm() - sphere.radius * sphere.radius) {}
  // An origin inside the sphere (the UAV's own hull, say) sees through it: no ray hits it.
  bool seesThrough() const { return c_ <= 0.0; }
  double distance(const Eigen::Vector3d& unitDirection) const {
    constexpr double kNone = std::numeric_limits<double>::infinity();
    if (seesThrough()) return kNone;
    const double b = offset_.dot(unitDirection);
    if (b >= 0.0) return kNone;
    const double discriminant = b * b - c_;
    if (discriminant < 0.0) return kNone;
    return -b - std::sqrt(discriminant);
  }

 private:
  Eigen::Vector3d offset_;  // origin - centre
  double c_;                // |offset|^2 - radius^2
};

}  // namespace coinspect::sensing
