#include "coinspect/planning/viewpoint.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <cmath>

#include "coinspect/core/random.h"
#include "coinspect/planning/coverage.h"

namespace coinspect::planning {
namespace {

using mapping::CellState;
constexpr double kDeg = M_PI / 180.0;

// Distance from `point` to the optical axis ray of the viewpoint.
double axisMiss(const Viewpoint& view, const Vec3& point) {
  const Vec3 axis = opticalAxis(view.bodyYaw, view.gimbal);
  const Vec3 to = point - view.camera;
  EXPECT_GT(to.dot(axis), 0.0);  // in front of the camera, not behind
  return (to - to.dot(axis) * axis).norm();
}

void checkConsistent(const Viewpoint& view, const ViewpointOptions& options) {
  EXPECT_LT((view.body + Eigen::AngleAxisd(view.bodyYaw, Vec3::UnitZ()) * options.cameraOffset -
             view.camera)
                .norm(),
            1e-12);
  EXPECT_LE(std::abs(view.gimbal.pitch), options.limits.pitchMax);
  EXPECT_LE(std::abs(view.gimbal.yaw), 1e-9);  // the body faces the patch
}

TEST(Viewpoint, FacesAWallAtTheFullResolutionDistance) {
  ViewpointOptions options;
  const SurfacePatch wall{Vec3(5, 3, 10), Vec3(0, -1, 0)};
  const Viewpoint view = makeViewpoint(wall, options);
  const double d = fullResolutionDistance(options.optics);
  EXPECT_NEAR(d, 7.356, 1e-3);
  EXPECT_LT((view.camera - Vec3(5, 3 - d, 10)).norm(), 1e-12);
  EXPECT_NEAR(view.viewingDistance, d, 1e-12);
  EXPECT_NEAR(view.bodyYaw, M_PI / 2.0, 1e-12);  // looking along +y
  EXPECT_NEAR(view.gimbal.pitch, 0.0, 1e-12);
  EXPECT_LT(axisMiss(view, wall.centre), 1e-6);
  checkConsistent(view, options);
  // The camera sits 0.2 m ahead of and 0.3 m below the body.
  EXPECT_LT((view.body - Vec3(5, 3 - d - 0.2, 10.3)).norm(), 1e-12);
}

TEST(Viewpoint, RandomPatchesAreAimedExactlyWithinGimbalLimits) {
  Rng rng(5);
  ViewpointOptions options;
  options.distance = 5.0;
  for (int i = 0; i < 200; ++i) {
    const SurfacePatch patch{Vec3(rng.uniform(-50, 50), rng.uniform(-50, 50), rng.uniform(0, 60)),
                             Vec3(rng.normal(), rng.normal(), rng.normal()).normalized()};
    const Viewpoint view = makeViewpoint(patch, options);
    EXPECT_LT(axisMiss(view, patch.centre), 1e-6);
    EXPECT_NEAR(view.viewingDistance, 5.0, 1e-9);
    checkConsistent(view, options);
    // Within the pitch limit the camera is on the normal; beyond it, leaned to the limit.
    const double elevation = std::asin(patch.normal.z());
    if (std::abs(elevation) < 80.0 * kDeg - 1e-6)
      EXPECT_LT((view.camera - (patch.centre + 5.0 * patch.normal)).norm(), 1e-9);
    else
      EXPECT_NEAR(std::abs(view.gimbal.pitch), 80.0 * kDeg, 1e-6);
  }
}

TEST(Viewpoint, RoofsAreSeenAtThePitchLimitFromThePreferredSide) {
  ViewpointOptions options;
  options.preferredYaw = M_PI;  // approach heading west: stand east of the patch
  const SurfacePatch roof{Vec3(0, 0, 20), Vec3(0, 0, 1)};
  const Viewpoint view = makeViewpoint(roof, options);
  EXPECT_NEAR(view.gimbal.pitch, 80.0 * kDeg, 1e-6);
  EXPECT_GT(view.camera.x(), 0.0);
  EXPECT_NEAR(view.bodyYaw, M_PI, 1e-9);
  EXPECT_LT(axisMiss(view, roof.centre), 1e-6);
  const SurfacePatch ceiling{Vec3(0, 0, 20), Vec3(0, 0, -1)};
  const Viewpoint below = makeViewpoint(ceiling, options);
  EXPECT_NEAR(below.gimbal.pitch, -80.0 * kDeg, 1e-6);
  EXPECT_LT(axisMiss(below, ceiling.centre), 1e-6);
}

TEST(Viewpoint, LiftedToTheMinimumHeightWithinThePitchLimit) {
  ViewpointOptions options;
  options.minHeight = 3.0;
  const SurfacePatch low{Vec3(0, 0, 0.5), Vec3(1, 0, -0.3).normalized()};
  const Viewpoint view = makeViewpoint(low, options);
  EXPECT_NEAR(view.camera.z(), 3.0, 1e-12);
  EXPECT_LT(axisMiss(view, low.centre), 1e-6);
  checkConsistent(view, options);
  // Lifting straight above a floor patch would be too steep: the camera moves away instead.
  options.minHeight = 60.0;
  const SurfacePatch floor{Vec3(0, 0, 0), Vec3(1, 0, 0.2).normalized()};
  const Viewpoint high = makeViewpoint(floor, options);
  EXPECT_NEAR(high.camera.z(), 60.0, 1e-9);
  EXPECT_NEAR(high.gimbal.pitch, 80.0 * kDeg, 1e-6);
  EXPECT_LT(axisMiss(high, floor.centre), 1e-6);
}

TEST(Viewpoint, PushedOutOfBlockedCellsAlongTheLineOfSight) {
  VoxelGrid grid(Vec3(-20, -20, 0), 0.5, Index3(80, 80, 40), CellState::Free);
  // A beam across the nominal body position (x about 7.56 in front of a wall facing +x).
  for (int y = 0; y < 80; ++y)
    for (int x = 53; x <= 56; ++x)
      for (int z = 18; z <= 22; ++z)
        grid.set(Index3(x, y, z), CellState::Occupied);
  grid.computeClearance(5.0, false);
  ViewpointOptions options;
  options.grid = &grid;
  options.pathOptions.clearance = 0.5;
  const SurfacePatch wall{Vec3(0, 0, 10), Vec3(1, 0, 0)};
  const Viewpoint view = makeViewpoint(wall, options);
  ASSERT_TRUE(view.free);
  EXPECT_TRUE(cellTraversable(grid, grid.cellOf(view.body), options.pathOptions));
  EXPECT_GT(std::abs(view.viewingDistance - fullResolutionDistance(options.optics)), 0.4);
  EXPECT_LT(axisMiss(view, wall.centre), 1e-6);
  checkConsistent(view, options);
}

TEST(Viewpoint, TurnedAwayFromTheNormalWhenItsWholeLineIsBlocked) {
  VoxelGrid grid(Vec3(-20, -20, 0), 0.5, Index3(80, 80, 40), CellState::Free);
  // A thin post on the normal of a wall facing +x, from 1 m out to beyond every push, and the
  // wall itself (x < 0).
  for (int x = 0; x < 80; ++x)
    for (int y = 0; y < 80; ++y)
      for (int z = 0; z < 40; ++z) {
        const Vec3 c = grid.centre(Index3(x, y, z));
        const bool post = c.x() > 1.0 && std::abs(c.y()) < 0.5 && std::abs(c.z() - 10.0) < 3.0;
        if (post || c.x() < 0.0) grid.set(Index3(x, y, z), CellState::Occupied);
      }
  grid.computeClearance(5.0, false);
  ViewpointOptions options;
  options.grid = &grid;
  options.pathOptions.clearance = 0.5;
  const SurfacePatch wall{Vec3(0.01, 0, 10), Vec3(1, 0, 0)};
  EXPECT_FALSE(makeViewpoint(wall, options).free);  // the normal's line only

  options.obliqueAngles = {30 * kDeg, 55 * kDeg};
  const Viewpoint view = makeViewpoint(wall, options);
  ASSERT_TRUE(view.free);
  EXPECT_TRUE(cellTraversable(grid, grid.cellOf(view.body), options.pathOptions));
  const Vec3 seen = (view.camera - wall.centre).normalized();
  EXPECT_NEAR(std::acos(seen.dot(wall.normal)), 30 * kDeg, 1e-6);  // the first angle works
  EXPECT_NEAR(seen.z(), 0.0, 1e-9);                                // a horizontal side first
  EXPECT_TRUE(lineOfSight(grid, view.camera, wall.centre + 0.75 * seen, false));
  EXPECT_LT(axisMiss(view, wall.centre), 1e-6);
  checkConsistent(view, options);

  // Walled in on every side but the blocked normal: nothing free, the straight view returned.
  for (int x = 0; x < 80; ++x)
    for (int y = 0; y < 80; ++y)
      for (int z = 0; z < 40; ++z) {
        const Vec3 c = grid.centre(Index3(x, y, z));
        if (c.x() > 0.5 && c.x() < 1.0) grid.set(Index3(x, y, z), CellState::Occupied);
      }
  grid.computeClearance(5.0, false);
  EXPECT_FALSE(makeViewpoint(wall, options).free);
}

TEST(Viewpoint, AimGimbalMatchesTheSimulatorConvention) {
  // Target 10 m ahead-left and 10 m below a body heading north: gimbal yaw +45 deg, pitch down.
  const AimAngles aim = aimGimbal(Vec3(0, 0, 20), M_PI / 2.0, Vec3(-10, 10, 20 - std::sqrt(200.0)));
  EXPECT_NEAR(aim.yaw, 45.0 * kDeg, 1e-12);
  EXPECT_NEAR(aim.pitch, 45.0 * kDeg, 1e-12);
  EXPECT_NEAR(inspectionSpeed(CameraOptics{}, 7.356, 5.0), 2.0, 1e-3);
  EXPECT_EQ(inspectionSpeed(CameraOptics{}, 7.356, 1.0), 1.0);
}

}  // namespace
}  // namespace coinspect::planning
