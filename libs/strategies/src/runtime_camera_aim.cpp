#include "coinspect/strategies/runtime/camera_aim.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>

#include "coinspect/planning/viewpoint.h"

namespace coinspect::strategies::runtime {

Vec3 cameraPosition(const agent::Odometry& odometry, const agent::CameraInfo& camera) {
  const Eigen::Matrix3d body = (Eigen::AngleAxisd(odometry.yaw, Vec3::UnitZ()) *
                                Eigen::AngleAxisd(odometry.pitch, Vec3::UnitY()) *
                                Eigen::AngleAxisd(odometry.roll, Vec3::UnitX()))
                                   .toRotationMatrix();
  return odometry.position + body * camera.positionInBody;
}

agent::GimbalCommand aimCamera(const agent::Odometry& odometry, const agent::CameraInfo& camera,
                               const agent::GimbalState& gimbal, const Vec3& target) {
  const auto aim = planning::aimGimbal(cameraPosition(odometry, camera), odometry.yaw, target);
  const auto clampTo = [](double value, double limit) {
    return limit > 0.0 ? std::clamp(value, -limit, limit) : value;
  };
  return agent::GimbalCommand::angles(clampTo(aim.pitch, gimbal.pitchMax),
                                      clampTo(aim.yaw, gimbal.yawMax));
}

double headingTowards(const Vec3& from, const Vec3& target, double fallback) {
  const Vec3 d = target - from;
  return std::hypot(d.x(), d.y()) > 1e-6 ? std::atan2(d.y(), d.x()) : fallback;
}

planning::CameraOptics cameraOptics(const agent::CameraInfo& camera) {
  planning::CameraOptics optics;
  if (camera.focalLength > 0.0) optics.focalLength = camera.focalLength;
  if (camera.pixelSize > 0.0) optics.pixelSize = camera.pixelSize;
  if (camera.exposureTime > 0.0) optics.exposure = camera.exposureTime;
  if (camera.desiredMmPerPixel > 0.0) optics.desiredMmPerPixel = camera.desiredMmPerPixel;
  return optics;
}

}  // namespace coinspect::strategies::runtime
