#include "coinspect/sensing/camera_model.h"

#include <algorithm>
#include <cmath>

#include "coinspect/core/error.h"

namespace coinspect::sensing {

double nominalDistance(const CameraSpec& spec) {
  // r_des is in mm/px, hence the 0.001.
  return spec.focalLength / spec.pixelSize * 0.001 * spec.desiredMmPerPixel;
}

double candidateRadius(const CameraSpec& spec) {
  const double l = nominalDistance(spec);
  const double sideH = l / std::cos(spec.horizontalFov / 2.0);
  const double sideV = l * std::tan(spec.verticalFov / 2.0);
  return std::sqrt(sideH * sideH + sideV * sideV) + 5.0;
}

double frontalMmPerPixel(const CameraSpec& spec, double distance) {
  return spec.pixelSize / spec.focalLength * 1000.0 * distance;
}

Eigen::Matrix3d rotationZ(double angle) {
  const double c = std::cos(angle), s = std::sin(angle);
  Eigen::Matrix3d r;
  r << c, -s, 0, s, c, 0, 0, 0, 1;
  return r;
}

Eigen::Matrix3d rotationY(double angle) {
  const double c = std::cos(angle), s = std::sin(angle);
  Eigen::Matrix3d r;
  r << c, 0, s, 0, 1, 0, -s, 0, c;
  return r;
}

Eigen::Matrix3d rotationX(double angle) {
  const double c = std::cos(angle), s = std::sin(angle);
  Eigen::Matrix3d r;
  r << 1, 0, 0, 0, c, -s, 0, s, c;
  return r;
}

Eigen::Matrix3d bodyRotation(const CaptureState& state) {
  return rotationZ(state.yaw) * rotationY(state.pitch) * rotationX(state.roll);
}

Eigen::Matrix3d stabilizerRotation(const CaptureState& state) {
  // The reference composes R_WB Rx(-roll) Ry(-pitch), which is exactly Rz(yaw); building Rz
  // directly avoids the rounding of the product.
  return rotationZ(state.yaw);
}

Eigen::Matrix3d gimbalRotation(double gimbalYaw, double gimbalPitch) {
  return rotationZ(gimbalYaw) * rotationY(gimbalPitch);
}

CameraPose cameraPose(const CameraSpec& spec, const CaptureState& state) {
  CameraPose pose;
  pose.position = state.position + bodyRotation(state) * spec.positionInBody;
  pose.rotation = stabilizerRotation(state) * gimbalRotation(state.gimbalYaw, state.gimbalPitch);
  return pose;
}

CameraTwist cameraTwist(const CameraSpec& spec, const CaptureState& state) {
  const Vec3& wB = state.angularVelocity;
  const double cp = std::cos(state.pitch);
  // Euler yaw rate of a Z-Y-X attitude; singular at pitch = +-90 deg like the reference.
  const double yawRate = (std::sin(state.roll) * wB.y() + std::cos(state.roll) * wB.z()) / cp;
  CameraTwist twist;
  twist.linear = state.linearVelocity + bodyRotation(state) * wB.cross(spec.positionInBody);
  // d/dt (Rz(a) Ry(b)) (Rz(a) Ry(b))^T = [(0, 0, da) + Rz(a) (0, db, 0)]x: the vector form of the
  // reference's R_WS dR_SC R_WC^T term.
  const double a = state.gimbalYaw;
  const Vec3 gimbalRate(-std::sin(a) * state.gimbalPitchRate, std::cos(a) * state.gimbalPitchRate,
                        state.gimbalYawRate);
  twist.angular = Vec3(0.0, 0.0, yawRate) + stabilizerRotation(state) * gimbalRate;
  return twist;
}

CaptureState aimCamera(const CameraSpec& spec, const Vec3& target, const Vec3& viewDirection,
                       double standoff) {
  COINSPECT_ASSERT(viewDirection.norm() > 0.0);
  const Vec3 d = viewDirection.normalized();
  CaptureState state;
  state.yaw = std::atan2(d.y(), d.x());
  state.gimbalPitch = -std::asin(std::clamp(d.z(), -1.0, 1.0));
  const Vec3 cameraPosition = target - standoff * d;
  state.position = cameraPosition - rotationZ(state.yaw) * spec.positionInBody;
  return state;
}

namespace {

double wrapToPi(double angle) {
  // Same result as the reference's wrapToPi for finite angles: into [-pi, pi).
  double wrapped = std::fmod(angle + M_PI, 2.0 * M_PI);
  if (wrapped < 0.0) wrapped += 2.0 * M_PI;
  return wrapped - M_PI;
}

}  // namespace

Gimbal::Gimbal(const CameraSpec& spec)
    : pitchMax_(spec.gimbalPitchMax), yawMax_(spec.gimbalYawMax), rateMax_(spec.gimbalRateMax) {}

void Gimbal::commandAngles(double pitch, double yaw, double now) {
  mode_ = Mode::Angle;
  targetPitch_ = pitch;
  targetYaw_ = yaw;
  lastCommand_ = now;
}

void Gimbal::commandRates(double pitchRate, double yawRate, double now) {
  mode_ = Mode::Rate;
  commandPitchRate_ = pitchRate;
  commandYawRate_ = yawRate;
  lastCommand_ = now;
}

void Gimbal::update(double now) {
  const double dt = 1.0 / kUpdateRate;
  if (mode_ == Mode::Rate && now - lastCommand_ > 2.0 / kUpdateRate) {
    // A stale rate command: hold the current angles.
    mode_ = Mode::Angle;
    targetPitch_ = pitch_;
    targetYaw_ = yaw_;
  }
  if (mode_ == Mode::Angle) {
    const double pitchTarget = std::clamp(wrapToPi(targetPitch_), -pitchMax_, pitchMax_);
    const double yawTarget = std::clamp(wrapToPi(targetYaw_), -yawMax_, yawMax_);
    pitchRate_ = std::clamp((pitchTarget - pitch_) * kUpdateRate, -rateMax_, rateMax_);
    yawRate_ = std::clamp((yawTarget - yaw_) * kUpdateRate, -rateMax_, rateMax_);
    pitch_ += pitchRate_ * dt;
    yaw_ += yawRate_ * dt;
  } else if (mode_ == Mode::Rate) {
    pitchRate_ = std::clamp(commandPitchRate_, -rateMax_, rateMax_);
    pitch_ = std::clamp(pitch_ + pitchRate_ * dt, -pitchMax_, pitchMax_);
    yawRate_ = std::clamp(commandYawRate_, -rateMax_, rateMax_);
    yaw_ = std::clamp(yaw_ + yawRate_ * dt, -yawMax_, yawMax_);
  }
}

void Gimbal::applyTo(CaptureState& state) const {
  state.gimbalPitch = pitch_;
  state.gimbalYaw = yaw_;
  state.gimbalPitchRate = pitchRate_;
  state.gimbalYawRate = yawRate_;
}

}  // namespace coinspect::sensing
