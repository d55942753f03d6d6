// Shared helpers of the vehicle tests: the shipped airframes and a command-streaming flight loop.
#pragma once

#include <functional>
#include <map>
#include <string>

#include "coinspect/testing/paths.h"
#include "coinspect/vehicle/airframe.h"
#include "coinspect/vehicle/multirotor.h"

namespace coinspect::vehicle::testing {

constexpr double kPhysicsStep = 0.0025;  // s, the sim's 400 Hz tick
constexpr double kDegree = M_PI / 180.0;

inline const Airframe& shippedAirframe(const std::string& name) {
  static const std::map<std::string, Airframe> airframes =
      loadAirframes(::coinspect::testing::sourceDir() / "share" / "coinspect" / "airframes.ini");
  return airframes.at(name);
}

// Streams `setpoint` at 20 Hz (every 20 physics steps) for `seconds`, calling `check` after
// every physics step.
inline void fly(Multirotor& vehicle, const Setpoint& setpoint, double seconds,
                const std::function<void(const Multirotor&)>& check = {}) {
  const int steps = static_cast<int>(seconds / kPhysicsStep + 0.5);
  for (int i = 0; i < steps; ++i) {
    if (i % 20 == 0) vehicle.command(setpoint, vehicle.state().time);
    vehicle.advance(kPhysicsStep);
    if (check) check(vehicle);
  }
}

// Flies the vehicle from the ground to hover at `position` and lets it settle (the takeoff
// overshoots: the vertical command is clamped to [0.3 g, 2 g]).
inline void takeOffTo(Multirotor& vehicle, const Vec3& position, double yaw = 0.0) {
  fly(vehicle, positionSetpoint(position, yaw), 25.0);
}

}  // namespace coinspect::vehicle::testing
