// The multirotor's equations of motion (private to the library).
//
// State y (10 numbers): position p (3, world), velocity v (3, world), roll, pitch, yaw (ZYX),
// yaw rate r. Input (constant between control ticks): AttitudeCommand.
//   roll'  = L tanh((roll_c - roll) / (tau L))    first-order response of time constant tau,
//   pitch' = L tanh((pitch_c - pitch) / (tau L))  smoothly bounded by the tilt rate limit L
//   yaw'   = r,   r' = (r_c - r) / tau            yaw rate follows its command with lag tau
//   p' = v,   m v' = T R e3 - m g e3 - c v        thrust along body z, gravity, linear drag
// While resting on the ground (grounded), p' = v' = 0. tanh instead of a hard clamp keeps the
// right-hand side smooth, which the variable-step integrator needs.
#pragma once

#include <array>
#include <cmath>

#include "coinspect/vehicle/airframe.h"
#include "coinspect/vehicle/tracking_controller.h"

namespace coinspect::vehicle {

constexpr double kGravity = 9.81;
constexpr int kStateSize = 10;
using StateVector = std::array<double, kStateSize>;

enum StateIndex { kPx = 0, kPy, kPz, kVx, kVy, kVz, kRoll, kPitch, kYaw, kYawRate };

// R e3 for ZYX angles: the direction of the thrust in the world.
inline Vec3 thrustDirection(double roll, double pitch, double yaw) {
  const double cr = std::cos(roll), sr = std::sin(roll);
  const double cp = std::cos(pitch), sp = std::sin(pitch);
  const double cy = std::cos(yaw), sy = std::sin(yaw);
  return Vec3(cy * sp * cr + sy * sr, sy * sp * cr - cy * sr, cp * cr);
}

// Body angular velocity from ZYX Euler angles and their rates.
inline Vec3 bodyRates(double roll, double pitch, double rollRate, double pitchRate,
                      double yawRate) {
  const double cr = std::cos(roll), sr = std::sin(roll);
  const double cp = std::cos(pitch), sp = std::sin(pitch);
  return Vec3(rollRate - yawRate * sp, pitchRate * cr + yawRate * cp * sr,
              -pitchRate * sr + yawRate * cp * cr);
}

// The right-hand side with its constant inputs; one per vehicle.
struct RigidBodyModel {
  const Airframe* airframe = nullptr;
  AttitudeCommand input;
  bool grounded = false;

  double tiltRate(double commanded, double current) const {
    const double limit = airframe->tiltRateLimit;
    return limit * std::tanh((commanded - current) / (airframe->attitudeTimeConstant * limit));
  }

  void derivative(const double* y, double* dy) const {
    const double tau = airframe->attitudeTimeConstant;
    dy[kRoll] = tiltRate(input.roll, y[kRoll]);
    dy[kPitch] = tiltRate(input.pitch, y[kPitch]);
    dy[kYaw] = y[kYawRate];
    dy[kYawRate] = (input.yawRate - y[kYawRate]) / tau;
    if (grounded) {
      for (int i = kPx; i <= kVz; ++i)
        dy[i] = 0.0;
      return;
    }
    const Vec3 direction = thrustDirection(y[kRoll], y[kPitch], y[kYaw]);
    const double perMass = input.thrust / airframe->mass;
    const double dragPerMass = airframe->dragCoefficient / airframe->mass;
    for (int i = 0; i < 3; ++i) {
      dy[kPx + i] = y[kVx + i];
      dy[kVx + i] = perMass * direction[i] - dragPerMass * y[kVx + i];
    }
    dy[kVz] -= kGravity;
  }
};

}  // namespace coinspect::vehicle
