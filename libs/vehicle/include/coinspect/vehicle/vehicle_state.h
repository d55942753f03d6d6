// The observable state of a vehicle (what odometry would report), in SI units.
#pragma once

#include "coinspect/world/mesh.h"

namespace coinspect::vehicle {

using world::Vec3;

struct VehicleState {
  Vec3 position = Vec3::Zero();         // m, world (ENU, z up)
  Vec3 velocity = Vec3::Zero();         // m/s, world
  double yaw = 0.0;                     // rad, Z-Y-X Euler angles, yaw in (-pi, pi]
  double pitch = 0.0;                   // rad
  double roll = 0.0;                    // rad
  Vec3 angularVelocity = Vec3::Zero();  // rad/s, body frame (x forward, y left, z up)
  double time = 0.0;                    // s, simulated
};

}  // namespace coinspect::vehicle
