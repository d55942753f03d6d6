// Pointing the camera: where it is on the body, the gimbal angles that put a world point on its
// optical axis (clamped to the gimbal's limits), and a body heading that faces a point so the
// gimbal's yaw stays near zero.
#pragma once

#include "coinspect/agent/commands.h"
#include "coinspect/agent/observations.h"
#include "coinspect/planning/camera_limits.h"

namespace coinspect::strategies::runtime {

using agent::Vec3;

// Camera position in the world: body position + full body attitude (Z-Y-X) x camera offset.
Vec3 cameraPosition(const agent::Odometry& odometry, const agent::CameraInfo& camera);

// Angle-mode gimbal command looking from the camera at `target`, clamped to the limits in
// `gimbal` (a zero limit means none is known).
agent::GimbalCommand aimCamera(const agent::Odometry& odometry, const agent::CameraInfo& camera,
                               const agent::GimbalState& gimbal, const Vec3& target);

// The camera's optics for the planning library (focal length, pixel size, exposure, r_des);
// a value the camera does not give (zero) keeps planning's default.
planning::CameraOptics cameraOptics(const agent::CameraInfo& camera);

// Heading (rad) from `from` towards `target` in the ground plane; `fallback` when straight above
// or below.
double headingTowards(const Vec3& from, const Vec3& target, double fallback);

}  // namespace coinspect::strategies::runtime
