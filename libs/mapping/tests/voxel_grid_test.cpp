#include "coinspect/mapping/voxel_grid.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace coinspect::mapping {
namespace {

// A small deterministic generator: next(n) draws an int in [0, n).
auto randomBelow(uint32_t seed) {
  return [seed](int below) mutable {
    seed = seed * 1664525u + 1013904223u;
    return static_cast<int>((seed >> 8) % static_cast<uint32_t>(below));
  };
}

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

// updateClearance after random edits inside a box equals a transform of the whole grid, value
// for value (the planners' grids are updated this way; any difference would change missions).
TEST(VoxelGrid, UpdatedClearanceEqualsTheWholeTransform) {
  auto next = randomBelow(12345);
  const Index3 size(40, 30, 20);
  // Sparse blockers, so that many clearances lie near the cap, where a too small update
  // window shows.
  VoxelGrid updated(Vec3(-3.0, 2.0, 0.0), 0.5, size, CellState::Free);
  for (int i = 0; i < 60; ++i)
    updated.set(Index3(next(40), next(30), next(20)),
                next(3) == 0 ? CellState::Unknown : CellState::Occupied);
  updated.computeClearance(2.2, true);
  for (int round = 0; round < 20; ++round) {
    // A box of edits (some rounds at the grid's edge, one round none), as a scan or a merge.
    const Index3 low(next(36), next(26), next(16));
    const Index3 extent(1 + next(8), 1 + next(8), 1 + next(6));
    const Index3 high = (low + extent).cwiseMin(size - Index3::Ones());
    Index3 changedLow = size, changedHigh = Index3::Constant(-1);
    for (int k = 0; round != 7 && k < 40; ++k) {
      const Index3 cell(low.x() + next(high.x() - low.x() + 1),
                        low.y() + next(high.y() - low.y() + 1),
                        low.z() + next(high.z() - low.z() + 1));
      updated.set(cell, next(4) == 0 ? CellState::Occupied : CellState::Free);
      changedLow = changedLow.cwiseMin(cell);
      changedHigh = changedHigh.cwiseMax(cell);
    }
    updated.updateClearance(changedLow, changedHigh);
    VoxelGrid whole = updated;
    whole.computeClearance(2.2, true);
    for (int z = 0; z < size.z(); ++z)
      for (int y = 0; y < size.y(); ++y)
        for (int x = 0; x < size.x(); ++x)
          ASSERT_EQ(updated.clearance(Index3(x, y, z)), whole.clearance(Index3(x, y, z)))
              << "round " << round << " cell " << x << " " << y << " " << z;
  }
}

// With a cap a few cells long, after the whole transform and after each update of a box of
// random edits, every value equals the capped brute-force distance (the transform drops values
// over the cap between its passes and transforms only the lines the window needs).
TEST(VoxelGrid, CappedClearanceMatchesBruteForceAfterUpdates) {
  auto next = randomBelow(777);
  const Index3 size(30, 24, 16);
  const double resolution = 0.25, cap = 1.3;
  VoxelGrid grid(Vec3(1.0, -2.0, 0.5), resolution, size, CellState::Free);
  const auto randomCell = [&](const Index3& low, const Index3& high) {
    return Index3(low.x() + next(high.x() - low.x() + 1), low.y() + next(high.y() - low.y() + 1),
                  low.z() + next(high.z() - low.z() + 1));
  };
  for (int i = 0; i < 40; ++i)
    grid.set(randomCell(Index3::Zero(), size - Index3::Ones()),
             next(2) == 0 ? CellState::Unknown : CellState::Occupied);
  // A solid slab: whole lines of blocking cells.
  for (int y = 0; y < size.y(); ++y)
    for (int x = 0; x < size.x(); ++x)
      grid.set(Index3(x, y, 0), CellState::Occupied);
  const auto forEachCell = [&](const auto& visit) {
    for (int z = 0; z < size.z(); ++z)
      for (int y = 0; y < size.y(); ++y)
        for (int x = 0; x < size.x(); ++x)
          visit(Index3(x, y, z));
  };
  const auto check = [&](const std::string& when) {
    std::vector<Index3> blocking;
    forEachCell([&](const Index3& cell) {
      if (grid.blocksClearance(grid.state(cell))) blocking.push_back(cell);
    });
    forEachCell([&](const Index3& cell) {
      double best = cap;
      for (const Index3& b : blocking)
        best = std::min(best, (b - cell).cast<double>().norm() * resolution);
      ASSERT_NEAR(grid.clearance(cell), best, 1e-5) << when << " cell " << cell.transpose();
    });
  };
  grid.computeClearance(cap, true);
  check("whole");
  for (int round = 0; round < 6; ++round) {
    const Index3 low(next(26), next(20), next(12));
    const Index3 high =
        (low + Index3(1 + next(6), 1 + next(6), 1 + next(5))).cwiseMin(size - Index3::Ones());
    for (int k = 0; k < 25; ++k)
      grid.set(randomCell(low, high), next(3) == 0 ? CellState::Occupied : CellState::Free);
    grid.updateClearance(low, high);
    check("round " + std::to_string(round));
  }
}

}  // namespace
}  // namespace coinspect::mapping
