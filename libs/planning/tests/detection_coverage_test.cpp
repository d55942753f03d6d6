#include "coinspect/planning/detection_coverage.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>

namespace coinspect::planning {
namespace {

using mapping::CellState;
using mapping::Index3;
using mapping::VoxelGrid;

// A 0.5 m grid, 20 x 20 x 10 m, free but for a block 4 x 4 x 3 m at x, y in [8, 12): its roof
// (normals up) and its -x wall (normals -x) are the surface.
struct BlockScene {
  VoxelGrid grid{Vec3::Zero(), 0.5, Index3(40, 40, 20), CellState::Free};
  std::vector<mapping::SurfaceVoxel> roof, wall;
  BlockScene() {
    for (int z = 0; z < 6; ++z)
      for (int y = 16; y < 24; ++y)
        for (int x = 16; x < 24; ++x)
          grid.set(Index3(x, y, z), CellState::Occupied);
    for (int y = 16; y < 24; ++y) {
      for (int x = 16; x < 24; ++x)
        roof.push_back({grid.centre(Index3(x, y, 5)), Vec3::UnitZ()});
      for (int z = 0; z < 6; ++z)
        wall.push_back({grid.centre(Index3(16, y, z)), -Vec3::UnitX()});
    }
    grid.computeClearance(3.0, true);
  }
};

InspectionPatch patchAt(const Vec3& centre, const Vec3& normal) {
  InspectionPatch patch;
  patch.centre = centre;
  patch.normal = normal;
  return patch;
}

TEST(DetectionCoverage, DetectsOnlyInsideRangeSectorBandFacingAndSight) {
  const BlockScene scene;
  const DetectorModel detector;
  // The -x wall's patch at (7.9, 10, 1.5): looked at from 3 m in front, level, heading +x.
  const auto patch = patchAt(Vec3(7.9, 10.0, 1.5), -Vec3::UnitX());
  const Vec3 front(4.9, 10.0, 1.5);
  EXPECT_TRUE(detects(detector, scene.grid, front, 0.0, patch, false));
  EXPECT_FALSE(detects(detector, scene.grid, Vec3(2.9, 10.0, 1.5), 0.0, patch, false));  // 5 m
  EXPECT_FALSE(detects(detector, scene.grid, front, 0.8, patch, false));  // heading away
  EXPECT_FALSE(detects(detector, scene.grid, Vec3(5.9, 10.0, 3.5), 0.0, patch, false));  // 45 deg
  // From behind its surface (inside the block's far side) and through the block.
  EXPECT_FALSE(detects(detector, scene.grid, Vec3(10.0, 10.0, 1.5), M_PI, patch, false));
  const auto farWall = patchAt(Vec3(12.1, 10.0, 1.5), Vec3::UnitX());
  EXPECT_FALSE(detects(detector, scene.grid, front, 0.0, farWall, false));
}

TEST(DetectionCoverage, RoofsAreSweptFromBesideAndAboveNotFromStraightAbove) {
  const BlockScene scene;
  const auto patches = groupSurface(scene.roof, 1.0);
  const DetectorModel detector;
  // Straight above the roof's centre the patches lie outside the elevation band.
  for (const auto& patch : patches)
    EXPECT_FALSE(detects(detector, scene.grid, Vec3(10, 10, 6), 0.0, patch, false));
  DetectionCoverageOptions options;
  options.clearance = 0.8;
  std::vector<uint32_t> uncoverable;
  const auto views = detectionViews(patches, scene.grid, options, &uncoverable);
  EXPECT_TRUE(uncoverable.empty());
  std::set<uint32_t> covered;
  for (const auto& view : views) {
    EXPECT_FALSE(view.covered.empty());
    EXPECT_GT(view.position.z(), 3.0);  // above the roof
    EXPECT_GE(scene.grid.clearance(scene.grid.cellOf(view.position)), options.clearance);
    for (const uint32_t j : view.covered) {
      EXPECT_TRUE(covered.insert(j).second) << "patch covered twice";
      EXPECT_TRUE(detects(detector, scene.grid, view.position, view.yaw, patches[j], false));
    }
  }
  EXPECT_EQ(covered.size(), patches.size());
  EXPECT_LT(views.size(), patches.size());  // 16 patches, a view sees several
}

TEST(DetectionCoverage, WallsAreSweptFromTheFreeSideAndBlockedPatchesReported) {
  BlockScene scene;
  auto patches = groupSurface(scene.wall, 1.0);
  const size_t wallPatches = patches.size();
  // A patch facing into the block's own inside has no free place in front of it.
  patches.push_back(patchAt(Vec3(10.0, 10.0, 1.0), Vec3::UnitX()));
  DetectionCoverageOptions options;
  options.clearance = 0.8;
  std::vector<uint32_t> uncoverable;
  const auto views = detectionViews(patches, scene.grid, options, &uncoverable);
  ASSERT_EQ(uncoverable.size(), 1u);
  EXPECT_EQ(uncoverable[0], wallPatches);
  for (const auto& view : views) {
    EXPECT_LT(view.position.x(), 8.0);  // in front of the -x wall
    EXPECT_GE(view.position.z(), options.minHeight);
  }
  // Places the explorer cannot reach do not count: none reachable, no view.
  const std::vector<uint8_t> nowhere(scene.grid.cellCount(), 0);
  auto unreachable = options;
  unreachable.reachable = &nowhere;
  EXPECT_TRUE(detectionViews(patches, scene.grid, unreachable).empty());
  // Deterministic.
  const auto again = detectionViews(patches, scene.grid, options);
  ASSERT_EQ(again.size(), views.size());
  for (size_t i = 0; i < views.size(); ++i)
    EXPECT_EQ(again[i].position, views[i].position);
}

TEST(DetectionCoverage, TheFootOfAWallIsSweptFromTheLowestSafeHeight) {
  // The ground is mapped (its layer occupied, as the LiDAR sees it), so a UAV of clearance 1.9 m
  // flies no lower than about 2 m; from there a wall's lowest metre is in the detector's band
  // only from about 3.7 m out. Places beside the patch or a little above it are either too low
  // or, for the next patch up, too steep for the foot (slei-c: 31 features on the foot of walls
  // never detected).
  BlockScene scene;
  for (int y = 0; y < 40; ++y)
    for (int x = 0; x < 40; ++x)
      scene.grid.set(Index3(x, y, 0), CellState::Occupied);
  scene.grid.computeClearance(3.0, true);
  DetectionCoverageOptions options;
  options.clearance = 1.9;
  options.groundZ = 0.0;
  std::vector<uint32_t> uncoverable;
  const auto views =
      detectionViews(groupSurface(scene.wall, 1.0), scene.grid, options, &uncoverable);
  EXPECT_TRUE(uncoverable.empty());
  // The wall's lowest visible strip, just above the ground layer, along the wall.
  for (const double y : {8.5, 10.0, 11.5}) {
    const auto foot = patchAt(Vec3(7.9, y, 0.55), -Vec3::UnitX());
    EXPECT_TRUE(std::any_of(views.begin(), views.end(), [&](const auto& view) {
      return detects(options.detector, scene.grid, view.position, view.yaw, foot, false);
    })) << y;
  }
  for (const auto& view : views)
    EXPECT_GE(scene.grid.clearance(scene.grid.cellOf(view.position)), options.clearance);
}

}  // namespace
}  // namespace coinspect::planning
