// The command a strategy sends to a UAV, with the reference's (CARIC unicon) semantics.
//
// - position given, velocity and acceleration zero: fly to the position and hover there;
// - position all zero (|position| < 0.01 m): velocity/acceleration control, the position terms
//   are off; if also |velocity| < 0.01 m/s, the velocity damping is off too (pure acceleration
//   feed-forward), as in the reference;
// - position, velocity and acceleration all zero: "yaw only": hold the position the vehicle has
//   at the next control tick and turn to `yaw`;
// - velocity and acceleration are feed-forward terms added to the position loop;
// - yaw is the heading (rad, world z, 0 = +x); the turn rate is limited by the airframe.
// A command holds until replaced; if none arrives for more than 0.1 s the vehicle holds the
// position and heading it has when the timeout is noticed (at a 20 Hz control tick).
#pragma once

#include "coinspect/world/mesh.h"

namespace coinspect::vehicle {

using world::Vec3;

struct Setpoint {
  Vec3 position = Vec3::Zero();      // m, world
  Vec3 velocity = Vec3::Zero();      // m/s, world
  Vec3 acceleration = Vec3::Zero();  // m/s^2, world (without gravity)
  double yaw = 0.0;                  // rad
};

// Below this norm the reference treats a position, velocity or acceleration as "zero".
constexpr double kSetpointZeroNorm = 0.01;

// True when every component is a finite number.
bool isFinite(const Setpoint& setpoint);

// A position-only setpoint (hover at `position` facing `yaw`).
inline Setpoint positionSetpoint(const Vec3& position, double yaw) {
  Setpoint s;
  s.position = position;
  s.yaw = yaw;
  return s;
}

// A velocity-control setpoint (position zero, see above).
inline Setpoint velocitySetpoint(const Vec3& velocity, double yaw) {
  Setpoint s;
  s.velocity = velocity;
  s.yaw = yaw;
  return s;
}

}  // namespace coinspect::vehicle
