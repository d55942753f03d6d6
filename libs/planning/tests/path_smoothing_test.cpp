#include "coinspect/planning/path_smoothing.h"

#include <gtest/gtest.h>

#include "coinspect/core/random.h"

namespace coinspect::planning {
namespace {

using mapping::CellState;

// Every point of the polyline (sampled finely) is in a traversable cell.
bool collisionFree(const VoxelGrid& grid, const std::vector<Vec3>& path,
                   const PathSearchOptions& options) {
  for (size_t i = 1; i < path.size(); ++i)
    for (int s = 0; s <= 1000; ++s) {
      const Vec3 p = path[i - 1] + s / 1000.0 * (path[i] - path[i - 1]);
      if (!cellTraversable(grid, grid.cellOf(p), options)) return false;
    }
  return true;
}

TEST(PathSmoothing, ShortcutsStayCollisionFreeKeepEndpointsAndShorten) {
  PathSearchOptions options;
  options.clearance = 0.75;
  int shortened = 0;
  for (uint64_t seed = 1; seed <= 10; ++seed) {
    Rng rng(seed);
    VoxelGrid grid(Vec3(0.0, 0.0, 0.0), 0.5, Index3(40, 30, 8), CellState::Free);
    for (int pillar = 0; pillar < 25; ++pillar) {
      const int x = 4 + rng.below(32), y = 3 + rng.below(24);
      for (int z = 0; z < 8; ++z)
        grid.set(Index3(x, y, z), CellState::Occupied);
    }
    grid.computeClearance(5.0, false);
    const Vec3 start(0.75, 0.75, 1.25), goal(19.25, 14.25, 2.75);
    const PathResult path = findPathAStar(grid, start, goal, options);
    if (path.status != PathStatus::Found) continue;
    ASSERT_TRUE(collisionFree(grid, path.points, options));
    const std::vector<Vec3> smooth = shortcutPath(grid, path.points, options);
    EXPECT_EQ(smooth.front(), path.points.front());
    EXPECT_EQ(smooth.back(), path.points.back());
    EXPECT_TRUE(collisionFree(grid, smooth, options)) << "seed " << seed;
    EXPECT_LE(pathLength(smooth), pathLength(path.points) + 1e-9);
    EXPECT_LE(smooth.size(), path.points.size());
    if (smooth.size() < path.points.size() / 2) ++shortened;
  }
  EXPECT_GE(shortened, 5);
}

// A shortcut that would cut through an expensive (soft-clearance) zone is refused even though it
// is traversable.
TEST(PathSmoothing, RefusesShortcutsThatCostMore) {
  VoxelGrid grid(Vec3::Zero(), 1.0, Index3(20, 20, 1), CellState::Free);
  grid.set(Index3(10, 10, 0), CellState::Occupied);
  grid.computeClearance(10.0, false);
  PathSearchOptions options;
  options.softClearance = 4.0;
  options.softWeight = 20.0;
  // A detour around the obstacle's costly neighbourhood.
  const std::vector<Vec3> detour{Vec3(2.5, 10.5, 0.5), Vec3(10.5, 17.5, 0.5),
                                 Vec3(18.5, 10.5, 0.5)};
  EXPECT_EQ(shortcutPath(grid, detour, options).size(), 3u);
  options.softWeight = 0.0;
  // The straight line touches the occupied cell: still refused, for traversability.
  EXPECT_EQ(shortcutPath(grid, detour, options).size(), 3u);
  const std::vector<Vec3> wide{Vec3(2.5, 12.5, 0.5), Vec3(10.5, 17.5, 0.5), Vec3(18.5, 12.5, 0.5)};
  EXPECT_EQ(shortcutPath(grid, wide, options).size(), 2u);
}

}  // namespace
}  // namespace coinspect::planning
