#include "coinspect/planning/ground_path.h"

#include <gtest/gtest.h>

#include "coinspect/core/error.h"

namespace coinspect::planning {
namespace {

// Every straight stretch of a path stays on free cells (sampled finely).
void expectClear(const GroundGrid& grid, const Vec2& start, const std::vector<Vec2>& path) {
  Vec2 from = start;
  for (const Vec2& to : path) {
    for (int i = 0; i <= 100; ++i)
      EXPECT_FALSE(grid.blocked(from + (to - from) * (i / 100.0)))
          << "blocked at " << (from + (to - from) * (i / 100.0)).transpose();
    from = to;
  }
}

TEST(GroundPath, GoesAroundAnInflatedBoxNotThroughIt) {
  GroundGrid grid(Vec2(-20, -20), Vec2(20, 20), 0.5);
  grid.blockRectangle(Vec2(0, 0), Vec2(1, 0), Vec2(3, 8), 1.0);
  EXPECT_TRUE(grid.blocked(Vec2(0, 0)));
  EXPECT_TRUE(grid.blocked(Vec2(3.8, 0)));   // within the inflation
  EXPECT_FALSE(grid.blocked(Vec2(4.3, 0)));  // beyond it
  const Vec2 start(-10, 0), goal(10, 0);
  const auto path = grid.path(start, goal);
  ASSERT_GE(path.size(), 2u);  // a straight line would cross the box
  EXPECT_EQ(path.back(), goal);
  expectClear(grid, start, path);
  double length = 0.0;
  Vec2 from = start;
  for (const Vec2& p : path)
    length += (p - from).norm(), from = p;
  // Around a 6 x 16 m box inflated by 1 m (corners rounded): at least the polygon around its
  // corners, 2 * hypot(6, 9) + 8 = 29.6 m, and within a few cells of it (a staircase along the
  // grid would be 2 * (6 + 9) + 8 = 38 m).
  EXPECT_LT(length, 30.5);
  EXPECT_GT(length, 29.0);
}

TEST(GroundPath, RotatedBoxesAndLearntWallsAreObstacles) {
  GroundGrid grid(Vec2(-10, -10), Vec2(10, 10), 0.25);
  const Vec2 diagonal = Vec2(1, 1).normalized();
  grid.blockRectangle(Vec2(0, 0), diagonal, Vec2(4, 0.5), 0.0);
  EXPECT_TRUE(grid.blocked(Vec2(2, 2)));    // along the rotated long axis
  EXPECT_FALSE(grid.blocked(Vec2(2, -2)));  // across it
  EXPECT_GT(grid.blockDisc(Vec2(-5, 5), 1.5), 0u);
  EXPECT_EQ(grid.blockDisc(Vec2(-5, 5), 1.5), 0u);  // nothing new the second time
  EXPECT_TRUE(grid.blocked(Vec2(-5, 6.2)));
  EXPECT_FALSE(grid.blocked(Vec2(-5, 7)));
  expectClear(grid, Vec2(-6, 2), grid.path(Vec2(-6, 2), Vec2(-4, 8)));
}

TEST(GroundPath, NoPathWhenWalledInAndBlockedEndsMoveToFreeCells) {
  GroundGrid grid(Vec2(0, 0), Vec2(20, 20), 0.5);
  grid.blockRectangle(Vec2(10, 10), Vec2(1, 0), Vec2(10, 0.25), 0.0);  // a wall across
  EXPECT_TRUE(grid.path(Vec2(5, 5), Vec2(5, 15)).empty());
  GroundGrid open(Vec2(0, 0), Vec2(20, 20), 0.5);
  open.blockDisc(Vec2(15, 15), 1.0);
  const auto path = open.path(Vec2(5, 5), Vec2(15, 15));  // the goal is inside the disc
  ASSERT_FALSE(path.empty());
  EXPECT_FALSE(open.blocked(path.back()));
  EXPECT_LT((path.back() - Vec2(15, 15)).norm(), 1.6);
  EXPECT_THROW(GroundGrid(Vec2(0, 0), Vec2(0, 5), 0.5), InputError);
}

TEST(GroundPath, NearestReachableStopsOutsideAWalledPlace) {
  GroundGrid grid(Vec2(0, 0), Vec2(30, 30), 0.5);
  // A 10 x 10 m block: its centre is 5 m from any free cell, beyond path()'s 3 m.
  grid.blockRectangle(Vec2(15, 15), Vec2(1, 0), Vec2(5, 5), 0.0);
  const Vec2 near = grid.nearestReachable(Vec2(2, 15), Vec2(15, 15));
  EXPECT_FALSE(grid.blocked(near));
  EXPECT_LT((near - Vec2(15, 15)).norm(), 5.6);
  EXPECT_GT((near - Vec2(15, 15)).norm(), 4.9);
  // A free goal is its own nearest cell (the centre of its cell).
  EXPECT_LT((grid.nearestReachable(Vec2(2, 2), Vec2(25.2, 3.1)) - Vec2(25.2, 3.1)).norm(), 0.36);
  // Walled off: the nearest place on the start's side of the wall, not the one behind it.
  GroundGrid split(Vec2(0, 0), Vec2(20, 20), 0.5);
  split.blockRectangle(Vec2(10, 10), Vec2(1, 0), Vec2(10, 0.5), 0.0);  // a wall along y = 10
  const Vec2 side = split.nearestReachable(Vec2(5, 5), Vec2(5, 12));
  EXPECT_LT(side.y(), 9.5);
  EXPECT_GT(side.y(), 8.5);
}

}  // namespace
}  // namespace coinspect::planning
