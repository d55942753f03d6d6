#include "coinspect/vehicle/tracking_controller.h"

#include <algorithm>
#include <cmath>

#include "rigid_body.h"

namespace coinspect::vehicle {
namespace {

// Tolerance on the timeout comparison, so that commands streamed at exactly 10 Hz never time out
// through floating-point noise in the tick times.
constexpr double kTimeEpsilon = 1e-9;

bool isZero(const Vec3& v) {
  return v.norm() < kSetpointZeroNorm;
}

}  // namespace

bool isFinite(const Setpoint& s) {
  return s.position.allFinite() && s.velocity.allFinite() && s.acceleration.allFinite() &&
         std::isfinite(s.yaw);
}

double wrapAngle(double angle) {
  double wrapped = std::remainder(angle, 2.0 * M_PI);  // in [-pi, pi]
  if (wrapped <= -M_PI) wrapped += 2.0 * M_PI;
  return wrapped;
}

void TrackingController::setCommand(const Setpoint& command, double time) {
  memory_.command = command;
  memory_.commandTime = time;
  memory_.commandPending = true;
}

void TrackingController::updateMode(double time, const VehicleState& state) {
  ControllerMemory& m = memory_;
  if (time - m.commandTime > kCommandTimeout + kTimeEpsilon) {
    // Reference: on timeout, hold where the vehicle is now (once), heading included.
    if (m.mode != ControlMode::Holding) {
      m.mode = ControlMode::Holding;
      m.reference = positionSetpoint(state.position, state.yaw);
    }
    m.commandPending = false;
    return;
  }
  if (!m.commandPending) return;
  m.commandPending = false;
  const Setpoint& c = m.command;
  if (isZero(c.position) && isZero(c.velocity) && isZero(c.acceleration)) {
    // "Yaw only": the position is captured when the mode is entered, the heading follows.
    if (m.mode != ControlMode::YawOnly) m.reference = positionSetpoint(state.position, c.yaw);
    m.reference.yaw = c.yaw;
    m.mode = ControlMode::YawOnly;
    return;
  }
  m.mode = ControlMode::Tracking;
  m.reference = c;
}

Vec3 TrackingController::accelerationCommand(const VehicleState& state) {
  const ControllerGains& g = airframe_.gains;
  const Setpoint& r = memory_.reference;
  // Reference: the sum adds the position error of each tick, whatever the mode (also in
  // velocity control, where the reference position is zero: a quirk kept for fidelity).
  Vec3& sum = memory_.positionErrorSum;
  sum += r.position - state.position;
  sum = sum.cwiseMax(-airframe_.integralClamp).cwiseMin(airframe_.integralClamp);

  const bool positionControl = !isZero(r.position);
  const bool velocityControl = positionControl || !isZero(r.velocity);
  const Vec3 w(g.wXY, g.wXY, g.wZ);
  const Vec3 zeta(g.zetaXY, g.zetaXY, g.zetaZ);
  const Vec3 ki(g.kiXY, g.kiXY, g.kiZ);
  Vec3 a = r.acceleration + ki.cwiseProduct(sum);
  if (positionControl) a += w.cwiseProduct(w).cwiseProduct(r.position - state.position);
  if (velocityControl) {
    a += 2.0 * zeta.cwiseProduct(w).cwiseProduct(r.velocity - state.velocity);
  }
  a.z() += kGravity;
  const double xy = airframe_.maxAccelerationXY;
  a.x() = std::clamp(a.x(), -xy, xy);
  a.y() = std::clamp(a.y(), -xy, xy);
  a.z() = std::clamp(a.z(), airframe_.minThrustAccel, airframe_.maxThrustAccel);
  return a;
}

std::optional<AttitudeCommand> TrackingController::tick(double time, const VehicleState& state) {
  if (memory_.mode == ControlMode::Idle && !memory_.commandPending) return std::nullopt;
  updateMode(time, state);
  const Vec3 a = accelerationCommand(state);

  // Desired body z along the acceleration, heading kept at the current yaw (the yaw is steered by
  // the rate command), roll and pitch clamped separately as in the reference.
  const Vec3 bodyZ = a.normalized();  // a.z() >= minThrustAccel >= 0 and |a| > 0 (validated)
  const Vec3 headingY(-std::sin(state.yaw), std::cos(state.yaw), 0.0);
  Vec3 bodyX = headingY.cross(bodyZ);
  if (bodyX.norm() > 1e-6) {
    bodyX.normalize();
    memory_.lastBodyX = bodyX;
  } else {
    bodyX = memory_.lastBodyX;
  }
  const Vec3 bodyY = bodyZ.cross(bodyX);
  // ZYX angles of R = [bodyX bodyY bodyZ]: roll = atan2(R21, R22), pitch = asin(-R20).
  const double tilt = airframe_.tiltLimit;
  AttitudeCommand out;
  out.roll = std::clamp(std::atan2(bodyY.z(), bodyZ.z()), -tilt, tilt);
  out.pitch = std::clamp(std::asin(std::clamp(-bodyX.z(), -1.0, 1.0)), -tilt, tilt);

  // Thrust: the commanded acceleration projected on the current body z (reference), times mass.
  const Vec3 currentBodyZ = thrustDirection(state.roll, state.pitch, state.yaw);
  out.thrust = std::max(0.0, airframe_.mass * a.dot(currentBodyZ));

  const double yawError = wrapAngle(memory_.reference.yaw - state.yaw);
  memory_.yawErrorSum = std::clamp(memory_.yawErrorSum + yawError, -airframe_.yawIntegralClamp,
                                   airframe_.yawIntegralClamp);
  const double rate =
      airframe_.gains.yawKp * yawError + airframe_.gains.yawKi * memory_.yawErrorSum;
  out.yawRate = std::clamp(rate, -airframe_.yawRateLimit, airframe_.yawRateLimit);
  return out;
}

}  // namespace coinspect::vehicle
