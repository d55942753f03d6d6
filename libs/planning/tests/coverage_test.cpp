#include "coinspect/planning/coverage.h"

#include <gtest/gtest.h>

#include <set>

namespace coinspect::planning {
namespace {

using mapping::CellState;
using mapping::Index3;
using mapping::VoxelGrid;

// A 1 m grid: free for x < 15, a wall of occupied cells at x = 15, unknown behind it.
struct WallScene {
  VoxelGrid grid{Vec3::Zero(), 1.0, Index3(30, 30, 20), CellState::Free};
  std::vector<mapping::SurfaceVoxel> surface;
  WallScene() {
    for (int z = 0; z < 20; ++z)
      for (int y = 0; y < 30; ++y) {
        for (int x = 16; x < 30; ++x)
          grid.set(Index3(x, y, z), CellState::Unknown);
        grid.set(Index3(15, y, z), CellState::Occupied);
        if (y >= 5 && y < 25) surface.push_back({grid.centre(Index3(15, y, z)), -Vec3::UnitX()});
      }
    grid.computeClearance(5.0, true);
  }
};

TEST(Coverage, GroupSurfaceBinsByPositionAndNormal) {
  std::vector<mapping::SurfaceVoxel> voxels = {{Vec3(0.5, 0.5, 0.5), Vec3::UnitX()},
                                               {Vec3(1.5, 0.5, 0.5), Vec3::UnitX()},
                                               {Vec3(1.5, 1.5, 0.5), -Vec3::UnitX()},
                                               {Vec3(2.5, 0.5, 0.5), Vec3::UnitX()}};
  const auto patches = groupSurface(voxels, 2.0);
  ASSERT_EQ(patches.size(), 3u);
  uint32_t total = 0;
  for (const auto& patch : patches)
    total += patch.weight;
  EXPECT_EQ(total, 4u);
  EXPECT_EQ(patches[0].weight, 2u);
  EXPECT_TRUE(patches[0].centre.isApprox(Vec3(1.0, 0.5, 0.5)));
  EXPECT_NE(patches[0].key, patches[1].key);
  EXPECT_NE(patches[0].key, patches[2].key);
  EXPECT_EQ(groupSurface(voxels, 2.0)[1].key, patches[1].key);
}

TEST(Coverage, GroundSurfaceIsTheUpwardLayerJustAboveTheGround) {
  const double ground = 2.0, resolution = 0.5;
  EXPECT_TRUE(isGroundSurface({Vec3(0, 0, 2.25), Vec3::UnitZ()}, ground, resolution));
  EXPECT_TRUE(
      isGroundSurface({Vec3(0, 0, 2.6), Vec3(0.3, 0, 0.95).normalized()}, ground, resolution));
  // A wall's foot faces sideways; a roof faces up but is higher; the underside faces down.
  EXPECT_FALSE(isGroundSurface({Vec3(0, 0, 2.25), Vec3::UnitX()}, ground, resolution));
  EXPECT_FALSE(isGroundSurface({Vec3(0, 0, 2.75), Vec3::UnitZ()}, ground, resolution));
  EXPECT_FALSE(isGroundSurface({Vec3(0, 0, 2.25), -Vec3::UnitZ()}, ground, resolution));
}

TEST(Coverage, LineOfSightStopsAtOccupiedAndUnknownCells) {
  const WallScene scene;
  EXPECT_TRUE(freeLineOfSight(scene.grid, Vec3(2.5, 2.5, 2.5), Vec3(14.5, 20.5, 10.5)));
  // The end cell may be the occupied surface itself, not what lies beyond it.
  EXPECT_TRUE(freeLineOfSight(scene.grid, Vec3(2.5, 20.5, 10.5), Vec3(15.5, 20.5, 10.5)));
  // A slanted ray enters the wall one cell early: blocked.
  EXPECT_FALSE(freeLineOfSight(scene.grid, Vec3(2.5, 2.5, 2.5), Vec3(15.5, 20.5, 10.5)));
  EXPECT_FALSE(freeLineOfSight(scene.grid, Vec3(2.5, 2.5, 2.5), Vec3(17.5, 20.5, 10.5)));
}

TEST(Coverage, UnknownCellsBlockTheLineOnlyWhenAsked) {
  WallScene scene;
  scene.grid.set(Index3(8, 11, 6), CellState::Unknown);  // on the line below
  const Vec3 a(2.5, 2.5, 2.5), b(14.5, 20.5, 10.5);
  EXPECT_FALSE(lineOfSight(scene.grid, a, b, true));
  EXPECT_FALSE(freeLineOfSight(scene.grid, a, b));
  EXPECT_TRUE(lineOfSight(scene.grid, a, b, false));
  scene.grid.set(Index3(8, 11, 6), CellState::Occupied);
  EXPECT_FALSE(lineOfSight(scene.grid, a, b, false));
}

// A band of unknown cells in front of the wall (never seen by a LiDAR ray) hides the wall unless
// `unknownHides` is false; the cameras themselves stay on free cells with the clearance.
TEST(Coverage, UnknownSpaceInFrontOfAWallHidesItOnlyWhenAsked) {
  WallScene scene;
  for (int z = 0; z < 20; ++z)
    for (int y = 0; y < 30; ++y)
      for (int x = 12; x < 15; ++x)
        scene.grid.set(Index3(x, y, z), CellState::Unknown);
  scene.grid.computeClearance(5.0, true);
  const auto patches = groupSurface(scene.surface, 2.0);
  CoverageOptions options;
  options.distance = 7.0;
  options.maxDistance = 8.5;
  options.clearance = 1.5;
  std::vector<uint32_t> uncoverable;
  EXPECT_TRUE(coverPatches(patches, scene.grid, options, &uncoverable).empty());
  EXPECT_EQ(uncoverable.size(), patches.size());
  options.unknownHides = false;
  const auto views = coverPatches(patches, scene.grid, options, &uncoverable);
  EXPECT_TRUE(uncoverable.empty());
  ASSERT_FALSE(views.empty());
  for (const auto& view : views) {
    EXPECT_EQ(scene.grid.state(scene.grid.cellOf(view.camera)), CellState::Free);
    EXPECT_GE(scene.grid.clearance(scene.grid.cellOf(view.camera)), options.clearance);
  }
}

TEST(Coverage, FewViewpointsCoverTheWholeWallFromTheFreeSide) {
  const WallScene scene;
  const auto patches = groupSurface(scene.surface, 2.0);
  CoverageOptions options;
  options.groundZ = 0.0;
  std::vector<uint32_t> uncoverable;
  const auto viewpoints = coverPatches(patches, scene.grid, options, &uncoverable);
  EXPECT_TRUE(uncoverable.empty());
  std::set<uint32_t> covered;
  for (const auto& viewpoint : viewpoints) {
    EXPECT_FALSE(viewpoint.covered.empty());
    EXPECT_LT(viewpoint.camera.x(), 15.0 - options.clearance + 1e-9);  // on the free side
    EXPECT_GE(viewpoint.camera.z(), options.minHeight);
    for (const uint32_t j : viewpoint.covered) {
      EXPECT_TRUE(covered.insert(j).second) << "patch covered twice";
      EXPECT_LE((patches[j].centre - viewpoint.camera).norm(), options.maxDistance);
    }
  }
  EXPECT_EQ(covered.size(), patches.size());
  // 400 m^2 of wall, ~25 m^2 per view cone: tens of viewpoints, not one per patch.
  EXPECT_LT(viewpoints.size(), patches.size() / 2);
  // Deterministic.
  const auto again = coverPatches(patches, scene.grid, options);
  ASSERT_EQ(again.size(), viewpoints.size());
  for (size_t i = 0; i < again.size(); ++i)
    EXPECT_EQ(again[i].camera, viewpoints[i].camera);
}

TEST(Coverage, PatchesWithoutASafeCameraAreReported) {
  WallScene scene;
  // Fill the free side: no camera position is free any more.
  for (int z = 0; z < 20; ++z)
    for (int y = 0; y < 30; ++y)
      for (int x = 0; x < 15; ++x)
        scene.grid.set(Index3(x, y, z), CellState::Unknown);
  scene.grid.computeClearance(5.0, true);
  const auto patches = groupSurface(scene.surface, 2.0);
  std::vector<uint32_t> uncoverable;
  EXPECT_TRUE(coverPatches(patches, scene.grid, CoverageOptions{}, &uncoverable).empty());
  EXPECT_EQ(uncoverable.size(), patches.size());
}

}  // namespace
}  // namespace coinspect::planning
