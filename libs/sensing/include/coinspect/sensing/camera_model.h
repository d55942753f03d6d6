// The inspection camera of a UAV: where it is, where it looks, how fast it moves, and the gimbal
// that points it. Reproduces the reference (gazebo_ppcom_plugin.cpp); doc/scoring.md has the
// formulas.
#pragma once

#include <Eigen/Core>

#include "coinspect/sensing/capture_state.h"
#include "coinspect/world/fleet.h"

namespace coinspect::sensing {

using world::CameraSpec;

// l = f / c * 0.001 * r_des: the distance (m) at which a frontal view has exactly r_des mm/px
// (7.356 m for f = 16 mm, c = 4.35 um, r_des = 2 mm/px).
double nominalDistance(const CameraSpec& spec);

// Radius (m) around the camera inside which interest points are evaluated at all:
// sqrt((l / cos(HFOV/2))^2 + (l * tan(VFOV/2))^2) + 5. Points farther away are never scored
// even when they would reach the 0.2 threshold (a property of the benchmark, kept in both modes).
double candidateRadius(const CameraSpec& spec);

// mm per pixel of a surface seen frontally at `distance` m on the optical axis: c/f * 1000 * d.
double frontalMmPerPixel(const CameraSpec& spec, double distance);

// Z-Y-X rotations (radians).
Eigen::Matrix3d rotationZ(double angle);
Eigen::Matrix3d rotationY(double angle);
Eigen::Matrix3d rotationX(double angle);

// R_WB = Rz(yaw) Ry(pitch) Rx(roll).
Eigen::Matrix3d bodyRotation(const CaptureState& state);
// The stabilizer cancels body roll and pitch: R_WS = R_WB Rx(-roll) Ry(-pitch) = Rz(yaw).
Eigen::Matrix3d stabilizerRotation(const CaptureState& state);
// R_SC = Rz(gimbalYaw) Ry(gimbalPitch).
Eigen::Matrix3d gimbalRotation(double gimbalYaw, double gimbalPitch);

struct CameraPose {
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();  // R_WC: columns are camera axes
  Vec3 position = Vec3::Zero();                            // p_C in the world frame
  Vec3 opticalAxis() const { return rotation.col(0); }
};

// p_C = p_B + R_WB * t_BC (the offset turns with the FULL body attitude, only the orientation is
// stabilised); R_WC = R_WS * R_SC.
CameraPose cameraPose(const CameraSpec& spec, const CaptureState& state);

// Velocity of the camera frame, both in the world frame.
struct CameraTwist {
  Vec3 linear = Vec3::Zero();   // v_WC = v_WB + R_WB (w_B x t_BC)
  Vec3 angular = Vec3::Zero();  // w_WC = w_WS + R_WS ((0, 0, da) + Rz(a) (0, db, 0))
};

// The stabilizer only yaws, at the Euler yaw rate of the body:
// w_WS = (0, 0, sin(roll)/cos(pitch) w_By + cos(roll)/cos(pitch) w_Bz).
CameraTwist cameraTwist(const CameraSpec& spec, const CaptureState& state);

// A static, level UAV whose camera sits at target - standoff * viewDirection and looks along
// viewDirection (need not be unit) at the target: body yaw = atan2(d_y, d_x), gimbal yaw 0,
// gimbal pitch = -asin(d_z). Used by tests, the score command and the benchmark.
CaptureState aimCamera(const CameraSpec& spec, const Vec3& target, const Vec3& viewDirection,
                       double standoff);

// The reference gimbal (updated at 20 Hz): angle mode drives each angle towards its target at
// rate clamp(20 (target - angle), +-rateMax); rate mode integrates the clamped commanded rate and
// clamps the angle to +-max. Quirks kept: in rate mode the reported rate stays at the command
// even while the angle sits at its limit; a rate command older than 0.1 s (strict >) turns into
// an angle command holding the current angles; before any command the gimbal does not move.
class Gimbal {
 public:
  static constexpr double kUpdateRate = 20.0;  // Hz

  explicit Gimbal(const CameraSpec& spec);

  // Targets are wrapped to [-pi, pi] and clamped to the limits when applied.
  void commandAngles(double pitch, double yaw, double now);
  void commandRates(double pitchRate, double yawRate, double now);
  // One tick of the 20 Hz loop at time `now` (s).
  void update(double now);

  double pitch() const { return pitch_; }
  double yaw() const { return yaw_; }
  double pitchRate() const { return pitchRate_; }
  double yawRate() const { return yawRate_; }
  // Copies angles and rates into a capture state.
  void applyTo(CaptureState& state) const;

 private:
  enum class Mode { None, Angle, Rate };
  double pitchMax_, yawMax_, rateMax_;
  Mode mode_ = Mode::None;
  double targetPitch_ = 0.0, targetYaw_ = 0.0;
  double commandPitchRate_ = 0.0, commandYawRate_ = 0.0;
  double lastCommand_ = 0.0;
  double pitch_ = 0.0, yaw_ = 0.0, pitchRate_ = 0.0, yawRate_ = 0.0;
};

}  // namespace coinspect::sensing
