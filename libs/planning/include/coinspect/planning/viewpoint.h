// Viewpoints: where a photographer should hold its camera to inspect a surface patch, and the
// body yaw and gimbal angles that put the patch on the optical axis.
//
// Gimbal convention (the simulator's, as coinspect::strategies::aimGimbal): the gimbal is
// stabilised in the frame S = Rz(bodyYaw); the optical axis is Rz(yaw) Ry(pitch) e_x in S, i.e.
// (cos yaw cos pitch, sin yaw cos pitch, -sin pitch): positive pitch looks down, positive yaw
// looks left. The camera sits at cameraOffset in the body frame; a hovering body is level, so
// camera = body + Rz(bodyYaw) cameraOffset.
#pragma once

#include <optional>
#include <vector>

#include "coinspect/mapping/voxel_grid.h"
#include "coinspect/planning/camera_limits.h"
#include "coinspect/planning/path_search.h"

namespace coinspect::planning {

struct AimAngles {
  double pitch = 0.0;  // rad, positive looks down
  double yaw = 0.0;    // rad, positive looks left
};

// Gimbal angles (unclamped) that point the optical axis from `camera` at `target` for a body
// with heading `bodyYaw`.
AimAngles aimGimbal(const Vec3& camera, double bodyYaw, const Vec3& target);

// The optical axis (unit, world frame) for a body yaw and gimbal angles.
Vec3 opticalAxis(double bodyYaw, const AimAngles& gimbal);

struct GimbalLimits {
  double pitchMax = 80.0 * 3.14159265358979323846 / 180.0;  // rad, |pitch| <= pitchMax
  double yawMax = 90.0 * 3.14159265358979323846 / 180.0;    // rad, |yaw| <= yawMax
};

struct SurfacePatch {
  Vec3 centre = Vec3::Zero();
  Vec3 normal = Vec3::UnitX();  // unit, pointing out of the surface toward free space
};

struct ViewpointOptions {
  CameraOptics optics;
  double distance = 0.0;              // m along the normal; <= 0: fullResolutionDistance(optics)
  Vec3 cameraOffset{0.2, 0.0, -0.3};  // camera in the body frame, m (CARIC's photographers)
  GimbalLimits limits;
  std::optional<double> minHeight;  // lift the camera to at least this z (m)
  // Heading used when the line of sight is vertical, and the side to tilt to when a patch faces
  // (almost) straight up or down and the view must lean to respect the pitch limit.
  double preferredYaw = 0.0;
  // With a grid: a body position that fails cellTraversable(grid, ., pathOptions) is moved along
  // the line of sight, alternately away from and toward the patch in steps of half a cell, up to
  // maxPush m either way (never closer than half the distance).
  const VoxelGrid* grid = nullptr;
  PathSearchOptions pathOptions;
  double maxPush = 3.0;
  // With a grid, when no body position on the normal's line is free: the same search on lines
  // turned away from the normal by each of these angles (rad, in this order), at 8 azimuths
  // around it, keeping the first free one whose line of sight to the patch crosses no occupied
  // cell. Empty: the normal's line only.
  std::vector<double> obliqueAngles;
};

struct Viewpoint {
  Vec3 camera = Vec3::Zero();
  Vec3 body = Vec3::Zero();
  double bodyYaw = 0.0;
  AimAngles gimbal;              // within the limits; the optical axis passes through the centre
  double viewingDistance = 0.0;  // |centre - camera|, m
  bool free = true;              // false: no traversable body position was found (grid given)
};

// The camera on the patch's normal at the viewing distance, leaned toward the horizontal when
// the line of sight would be steeper than the pitch limit, lifted to minHeight (then moved away
// horizontally if the lift made it too steep), pushed out of blocked cells; the body yaw faces
// the patch, so the gimbal yaw is 0; then, if that found no free place, the oblique lines.
Viewpoint makeViewpoint(const SurfacePatch& patch, const ViewpointOptions& options);

// Largest speed (m/s) for capturing while moving past a surface `viewingDistance` m away with
// q_blur = 1 (motion across the line of sight is at most the speed), capped at maxSpeed.
double inspectionSpeed(const CameraOptics& optics, double viewingDistance, double maxSpeed);

}  // namespace coinspect::planning
