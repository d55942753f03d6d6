#include "coinspect/planning/ground_drive.h"

#include <gtest/gtest.h>

namespace coinspect::planning {
namespace {

// A 2 x 16 m wall across x = 0 (inflated 0.5 m) on a 40 m square grid.
GroundGrid walledGround() {
  GroundGrid grid(Vec2(-20, -20), Vec2(20, 20), 0.25);
  grid.blockRectangle(Vec2(0, 0), Vec2(1, 0), Vec2(1, 8), 0.5);
  return grid;
}

bool clearOn(const GroundGrid& grid, const Vec2& a, const Vec2& b) {
  for (int i = 0; i <= 200; ++i)
    if (grid.blocked(a + (b - a) * (i / 200.0))) return false;
  return true;
}

TEST(GroundDrive, DrivesAroundWhatItKnows) {
  GroundDrive drive(walledGround());
  const Vec2 start(-10, 0), goal(10, 0);
  const Vec2 to = drive.step(start, goal, 0.0);
  EXPECT_NE(to, goal);  // straight would cross the wall
  EXPECT_TRUE(clearOn(walledGround(), start, to));
  EXPECT_GT(std::abs(to.y()), 8.0);  // round one of its ends
  EXPECT_EQ(drive.guesses(), 0u);
  EXPECT_FALSE(drive.there(goal));
  drive.step(goal + Vec2(0.3, 0.0), goal, 30.0);
  EXPECT_TRUE(drive.there(goal));
  EXPECT_FALSE(drive.there(start));  // not on the way there
}

TEST(GroundDrive, StandingStillWhileDrivingBlocksTheGroundAheadAndPlansAgain) {
  GroundDrive drive(walledGround());
  const Vec2 at(-10, 0), goal(10, 0);
  const Vec2 first = drive.step(at, goal, 0.0);
  EXPECT_EQ(drive.step(at, goal, 2.0), first);  // not yet: 3 s
  const Vec2 second = drive.step(at, goal, 3.5);
  EXPECT_EQ(drive.guesses(), 1u);
  EXPECT_TRUE(drive.ground().blocked(at + 0.8 * (first - at).normalized()));
  EXPECT_LT(second.y() * first.y(), 0.0);  // round the wall's other end now
  EXPECT_TRUE(clearOn(walledGround(), at, second));
  // Moving again: no more guesses.
  drive.step(at + Vec2(0.5, 0.0), goal, 5.0);
  drive.step(at + Vec2(1.0, 0.0), goal, 7.0);
  EXPECT_EQ(drive.guesses(), 1u);
}

// Held still for long in front of a wall, it keeps guessing; whatever it guessed, it drives
// only on paths over what it knows, never straight through the wall it knows.
TEST(GroundDrive, HeldStillItNeverDrivesThroughWhatItKnows) {
  const GroundGrid known = walledGround();
  GroundDrive drive(known);
  const Vec2 at(-10, 0), goal(10, 0);
  for (double t = 0.0; t <= 300.0; t += 0.5) {
    const Vec2 to = drive.step(at, goal, t);
    EXPECT_TRUE(clearOn(known, at, to)) << "at t = " << t << " to " << to.transpose();
  }
  EXPECT_GE(drive.guesses(), 50u);
}

// In a closed L-shaped corridor the one way to the goal is guessed blocked: no path is left, so
// the guesses go (what it knows stays) and it drives on along the corridor (not straight to the
// goal, through the walls it knows, as it did before it could forget).
TEST(GroundDrive, WithEveryWayGuessedBlockedItForgetsTheGuesses) {
  GroundGrid known(Vec2(-20, -20), Vec2(20, 20), 0.25);
  const auto wall = [&](double x, double y, double halfX, double halfY) {
    known.blockRectangle(Vec2(x, y), Vec2(1, 0), Vec2(halfX, halfY), 0.0);
  };
  // Free: y in (-0.5, 0.5) for x up to 5.5, then x in (4.5, 5.5) up to y = 14.75.
  wall(-4.625, -0.75, 10.625, 0.25);
  wall(-15.0, 0.0, 0.25, 1.0);
  wall(-5.375, 0.75, 9.875, 0.25);
  wall(4.25, 8.0, 0.25, 7.5);
  wall(5.75, 7.0, 0.25, 8.25);
  wall(5.0, 15.0, 1.0, 0.25);
  const Vec2 at(0, 0), goal(5, 10);
  ASSERT_FALSE(clearOn(known, at, goal));
  GroundDrive drive(known);
  const Vec2 corner = drive.step(at, goal, 0.0);
  EXPECT_TRUE(clearOn(known, at, corner));
  EXPECT_NEAR(corner.y(), 0.0, 0.5);
  EXPECT_EQ(drive.step(at, goal, 3.5), corner);  // guessed, then forgotten
  EXPECT_EQ(drive.forgotten(), 1u);
  EXPECT_EQ(drive.guesses(), 0u);
  EXPECT_FALSE(drive.ground().blocked(Vec2(0.8, 0)));
  EXPECT_TRUE(drive.ground().blocked(Vec2(0, 0.75)));  // what it knows stays
}

// A goal inside a ring it knows: it drives to the nearest place it can reach and waits there,
// without taking that for being stuck.
TEST(GroundDrive, AGoalNoPathReachesIsApproachedAndWaitedAtNotGuessedAround) {
  GroundGrid known(Vec2(-20, -20), Vec2(20, 20), 0.25);
  for (int k = 0; k < 4; ++k) {
    const double a = k * 1.5707963267948966;
    const Vec2 side(std::cos(a), std::sin(a));
    known.blockRectangle(5.0 * side, Vec2(-side.y(), side.x()), Vec2(5.5, 0.25), 0.0);
  }
  const Vec2 goal(0, 0);
  ASSERT_TRUE(known.path(Vec2(-12, 0), goal).empty());
  GroundDrive drive(known);
  const Vec2 to = drive.step(Vec2(-12, 0), goal, 0.0);
  EXPECT_FALSE(drive.there(goal));
  EXPECT_NEAR(to.x(), -5.5, 0.3);  // outside the ring's wall, nearest the goal
  EXPECT_NEAR(to.y(), 0.0, 0.3);
  for (double t = 1.0; t <= 60.0; t += 1.0) {
    EXPECT_EQ(drive.step(to, goal, t), to);
    EXPECT_TRUE(drive.there(goal));  // as near as it gets
  }
  EXPECT_EQ(drive.guesses(), 0u);
}

TEST(GroundDrive, AWallLearntIsKeptAndPlannedAround) {
  GroundDrive drive(GroundGrid(Vec2(-20, -20), Vec2(20, 20), 0.25));
  const Vec2 at(-10, 0), goal(10, 0);
  EXPECT_EQ(drive.step(at, goal, 0.0), goal);  // open ground: straight
  const size_t newly = drive.learn([](GroundGrid& g) { return g.blockDisc(Vec2(0, 0), 3.0); });
  EXPECT_GT(newly, 0u);
  const Vec2 to = drive.step(at, goal, 1.0);
  EXPECT_NE(to, goal);
  EXPECT_TRUE(clearOn(drive.ground(), at, to));
  EXPECT_EQ(drive.guesses(), 0u);
}

}  // namespace
}  // namespace coinspect::planning
