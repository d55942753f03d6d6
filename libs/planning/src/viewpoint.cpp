#include "coinspect/planning/viewpoint.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>

#include "coinspect/core/error.h"
#include "coinspect/planning/coverage.h"

namespace coinspect::planning {

AimAngles aimGimbal(const Vec3& camera, double bodyYaw, const Vec3& target) {
  // Direction in the stabilizer frame S = Rz(bodyYaw).
  const Vec3 d = Eigen::AngleAxisd(-bodyYaw, Vec3::UnitZ()) * (target - camera);
  AimAngles out;
  out.yaw = std::atan2(d.y(), d.x());
  out.pitch = std::atan2(-d.z(), std::hypot(d.x(), d.y()));
  return out;
}

Vec3 opticalAxis(double bodyYaw, const AimAngles& gimbal) {
  const double heading = bodyYaw + gimbal.yaw;
  return Vec3(std::cos(heading) * std::cos(gimbal.pitch),
              std::sin(heading) * std::cos(gimbal.pitch), -std::sin(gimbal.pitch));
}

double inspectionSpeed(const CameraOptics& optics, double viewingDistance, double maxSpeed) {
  return std::min(maxSpeed, blurFreeSpeed(optics, viewingDistance));
}

namespace {

constexpr double kVertical = 1e-9;  // horizontal extent below which a direction is vertical
constexpr double kHalfPi = 1.57079632679489661923;

// Unit horizontal direction of `v`, or the side opposite `preferredYaw` when `v` is vertical
// (the camera then stands there and faces the patch with heading preferredYaw).
Vec3 horizontalOf(const Vec3& v, double preferredYaw) {
  const Vec3 h(v.x(), v.y(), 0.0);
  if (h.norm() > kVertical) return h.normalized();
  return -Vec3(std::cos(preferredYaw), std::sin(preferredYaw), 0.0);
}

struct Pose {
  Vec3 body;
  double yaw;
};

Pose bodyFor(const Vec3& camera, const Vec3& centre, const ViewpointOptions& options) {
  const Vec3 toPatch = centre - camera;
  const double yaw = std::hypot(toPatch.x(), toPatch.y()) > kVertical
                         ? std::atan2(toPatch.y(), toPatch.x())
                         : options.preferredYaw;
  return {camera - Eigen::AngleAxisd(yaw, Vec3::UnitZ()) * options.cameraOffset, yaw};
}

// The camera on the patch's normal (makeViewpoint without the oblique lines).
Viewpoint viewAlongNormal(const SurfacePatch& patch, const ViewpointOptions& options) {
  COINSPECT_ASSERT(patch.normal.norm() > 0.0);
  const double distance =
      options.distance > 0.0 ? options.distance : fullResolutionDistance(options.optics);
  // A small margin keeps the final pitch strictly inside the limit despite rounding.
  const double steepest = std::min(options.limits.pitchMax - 1e-9, kHalfPi);
  const Vec3& centre = patch.centre;

  Vec3 out = patch.normal.normalized();  // from the patch toward the camera
  if (std::abs(std::asin(std::clamp(out.z(), -1.0, 1.0))) > steepest) {
    const double up = out.z() > 0.0 ? 1.0 : -1.0;
    out = std::cos(steepest) * horizontalOf(out, options.preferredYaw) +
          up * std::sin(steepest) * Vec3::UnitZ();
  }
  Vec3 camera = centre + distance * out;
  if (options.minHeight && camera.z() < *options.minHeight) {
    camera.z() = *options.minHeight;
    const Vec3 offset = camera - centre;
    const double rise = offset.z();
    const double horizontal = std::hypot(offset.x(), offset.y());
    if (rise > 0.0 && std::atan2(rise, horizontal) > steepest) {
      const Vec3 side = horizontalOf(offset, options.preferredYaw);
      camera = centre + side * (rise / std::tan(steepest)) + rise * Vec3::UnitZ();
    }
  }

  Viewpoint view;
  view.camera = camera;
  if (options.grid) {
    const VoxelGrid& grid = *options.grid;
    const auto freeAt = [&](const Vec3& cameraCandidate) {
      if (options.minHeight && cameraCandidate.z() < *options.minHeight - 1e-9) return false;
      const Pose pose = bodyFor(cameraCandidate, centre, options);
      return cellTraversable(grid, grid.cellOf(pose.body), options.pathOptions);
    };
    view.free = freeAt(camera);
    if (!view.free) {
      const Vec3 ray = (camera - centre).normalized();
      const double base = (camera - centre).norm();
      const double stride = 0.5 * grid.resolution();
      for (int k = 1; !view.free && k * stride <= options.maxPush + 1e-9; ++k)
        for (const double sign : {1.0, -1.0}) {
          const double along = base + sign * k * stride;
          if (along < 0.5 * base) continue;
          if (freeAt(centre + along * ray)) {
            view.camera = centre + along * ray;
            view.free = true;
            break;
          }
        }
    }
  }
  const Pose pose = bodyFor(view.camera, centre, options);
  view.body = pose.body;
  view.bodyYaw = pose.yaw;
  view.gimbal = aimGimbal(view.camera, pose.yaw, centre);
  view.viewingDistance = (centre - view.camera).norm();
  return view;
}

// The directions `angle` away from `normal` at 8 azimuths: the two horizontal sides first, then
// above and below, then the diagonals (a fixed order, so the choice is deterministic).
std::vector<Vec3> turnedAway(const Vec3& normal, double angle) {
  const Vec3 n = normal.normalized();
  Vec3 side = n.cross(Vec3::UnitZ());
  side = side.norm() > 1e-6 ? side.normalized() : Vec3::UnitX();
  const Vec3 up = side.cross(n).normalized();
  std::vector<Vec3> out;
  for (const double azimuth : {0.0, 4.0, 2.0, 6.0, 1.0, 3.0, 5.0, 7.0}) {
    const double phi = azimuth * kHalfPi / 2.0;
    out.push_back(std::cos(angle) * n +
                  std::sin(angle) * (std::cos(phi) * side + std::sin(phi) * up));
  }
  return out;
}

}  // namespace

Viewpoint makeViewpoint(const SurfacePatch& patch, const ViewpointOptions& options) {
  const Viewpoint straight = viewAlongNormal(patch, options);
  if (straight.free || !options.grid) return straight;
  // The camera's line of sight must not cross structure the straight line was blocked by; it
  // stops a cell and a half short of the patch, whose own surface is occupied.
  const double shortOfPatch = 1.5 * options.grid->resolution();
  for (const double angle : options.obliqueAngles)
    for (const Vec3& direction : turnedAway(patch.normal, angle)) {
      const Viewpoint view = viewAlongNormal({patch.centre, direction}, options);
      if (!view.free) continue;
      const Vec3 toCamera = (view.camera - patch.centre).normalized();
      if (lineOfSight(*options.grid, view.camera, patch.centre + shortOfPatch * toCamera, false))
        return view;
    }
  return straight;
}

}  // namespace coinspect::planning
