// Everything one camera evaluation needs to know about a UAV at the instant of a capture.
//
// Frames follow the reference (ntu-aris/rotors_simulator, gazebo_ppcom_plugin.cpp): W is the
// world frame (z up), B the body frame (x forward, y left, z up), S the stabilizer frame and C the
// camera frame (x = optical axis, y = left, z = up in the image). See doc/scoring.md.
#pragma once

#include <Eigen/Core>

#include "coinspect/world/mesh.h"

namespace coinspect::sensing {

using world::Vec3;

struct CaptureState {
  // Body origin in the world frame, metres.
  Vec3 position = Vec3::Zero();
  // Body attitude as Z-Y-X Euler angles, radians: R_WB = Rz(yaw) * Ry(pitch) * Rx(roll).
  // Positive pitch lowers the nose.
  double yaw = 0.0;
  double pitch = 0.0;
  double roll = 0.0;
  // Velocity of the body origin in the WORLD frame, m/s. (The reference's odometry carries it in
  // the body frame and rotates it by R_WB before use; callers holding a body-frame velocity must
  // do the same.)
  Vec3 linearVelocity = Vec3::Zero();
  // Angular velocity of the body in the BODY frame, rad/s (odometry twist.angular).
  Vec3 angularVelocity = Vec3::Zero();
  // Gimbal angles relative to the stabilizer frame, radians: R_SC = Rz(gimbalYaw) *
  // Ry(gimbalPitch). Positive pitch looks down, positive yaw looks left.
  double gimbalYaw = 0.0;
  double gimbalPitch = 0.0;
  // Gimbal angle rates, rad/s (as reported by the gimbal model, see camera_model.h).
  double gimbalYawRate = 0.0;
  double gimbalPitchRate = 0.0;
};

}  // namespace coinspect::sensing
