#include "coinspect/mapping/voxel_grid.h"

#include <gtest/gtest.h>

#include <cmath>

namespace coinspect::mapping {
namespace {

TEST(VoxelGrid, CellOfAndCentreAreInverse) {
  const VoxelGrid grid(Vec3(-2.0, 1.0, 0.5), 0.5, Index3(8, 6, 4));
  const Index3 cell(3, 2, 1);
  EXPECT_EQ(grid.cellOf(grid.centre(cell)), cell);
  EXPECT_EQ(grid.cellOf(Vec3(-2.1, 1.0, 0.5)), Index3(-1, 0, 0));
  EXPECT_FALSE(grid.contains(Index3(8, 0, 0)));
  EXPECT_EQ(grid.state(Index3(-1, 0, 0)), CellState::Unknown);
}

// The clearance field equals the brute-force distance to the nearest blocking cell.
TEST(VoxelGrid, ClearanceMatchesBruteForce) {
  VoxelGrid grid(Vec3::Zero(), 0.25, Index3(11, 7, 5), CellState::Free);
  const Index3 blocked[] = {{2, 3, 1}, {9, 0, 4}, {5, 6, 2}};
  for (const auto& cell : blocked)
    grid.set(cell, CellState::Occupied);
  grid.set(Index3(0, 0, 0), CellState::Unknown);
  for (const bool unknownBlocks : {false, true}) {
    grid.computeClearance(100.0, unknownBlocks);
    for (int z = 0; z < 5; ++z)
      for (int y = 0; y < 7; ++y)
        for (int x = 0; x < 11; ++x) {
          double best = 1e9;
          for (const auto& cell : blocked)
            best = std::min(best, (cell - Index3(x, y, z)).cast<double>().norm() * 0.25);
          if (unknownBlocks) best = std::min(best, Index3(x, y, z).cast<double>().norm() * 0.25);
          EXPECT_NEAR(grid.clearance(Index3(x, y, z)), best, 1e-5) << x << " " << y << " " << z;
        }
  }
  grid.computeClearance(0.6, false);
  EXPECT_FLOAT_EQ(grid.clearance(Index3(10, 6, 0)), 0.6f);
  EXPECT_FLOAT_EQ(grid.clearance(Index3(2, 3, 1)), 0.0f);
}

TEST(VoxelGrid, NothingBlockingGivesTheCap) {
  VoxelGrid grid(Vec3::Zero(), 1.0, Index3(4, 4, 4), CellState::Free);
  grid.computeClearance(3.0, true);
  EXPECT_FLOAT_EQ(grid.clearance(Index3(1, 2, 3)), 3.0f);
}

}  // namespace
}  // namespace coinspect::mapping
