// Time to fly a straight distance from rest to rest with a trapezoidal speed profile: the cost
// model SLEI3D's planners use (a = 1 m/s^2, v = 2 m/s in the reference code).
#pragma once

#include <cmath>

namespace coinspect::planning {

struct TravelLimits {
  double speed = 2.0;         // m/s, cruise
  double acceleration = 1.0;  // m/s^2, both to speed up and to brake
};

// Accelerate to `speed`, cruise, brake; when the distance is too short to reach the cruise
// speed, a symmetric triangle: 2 sqrt(d / a). (The reference code uses sqrt(2 d / a) there,
// which is the time to accelerate over d without braking; coinspect uses the exact profile.)
inline double travelTime(double distance, const TravelLimits& limits) {
  if (!(distance > 0.0)) return 0.0;
  const double v = limits.speed, a = limits.acceleration;
  const double ramps = v * v / a;  // distance covered speeding up plus braking
  if (distance >= ramps) return 2.0 * v / a + (distance - ramps) / v;
  return 2.0 * std::sqrt(distance / a);
}

}  // namespace coinspect::planning
