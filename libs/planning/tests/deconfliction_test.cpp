#include "coinspect/planning/deconfliction.h"

#include <gtest/gtest.h>

#include <cmath>

namespace coinspect::planning {
namespace {

// A kinematic robot flying straight to its goal at `speed`: the plan it would like.
TimedPath straightTo(double now, const Vec3& from, const Vec3& goal, double speed,
                     const DeconflictionOptions& options) {
  TimedPath path{now, options.step, {}};
  const int count = static_cast<int>(std::ceil(options.horizon / options.step));
  const double length = (goal - from).norm();
  for (int k = 0; k <= count; ++k) {
    const double along = std::min(length, k * options.step * speed);
    path.positions.push_back(length > 0.0 ? Vec3(from + along / length * (goal - from)) : from);
  }
  return path;
}

struct Encounter {
  double minDistance = 1e9;
  bool lowReached = false;
  int waits = 0, sidesteps = 0, holds = 0;
};

// Closed loop at 10 Hz: robot 0 (priority) flies straight to its goal and announces it; robot 1
// deconflicts every decision against that announcement and follows the chosen plan for one tick.
Encounter fly(const Vec3& start0, const Vec3& goal0, const Vec3& start1, const Vec3& goal1,
              const DeconflictionOptions& options) {
  const double speed = 2.0, tick = 0.1;
  Vec3 p0 = start0, p1 = start1;
  Encounter out;
  for (int k = 0; k < 600; ++k) {
    const double now = k * tick;
    const TimedPath announced = straightTo(now, p0, goal0, speed, options);
    const TimedPath desired = straightTo(now, p1, goal1, speed, options);
    // Robot 0 never yields to robot 1.
    EXPECT_EQ(deconflict(0, now, p0, announced, {{1, desired}}, options).action,
              YieldAction::Proceed);
    const DeconflictionResult choice = deconflict(1, now, p1, desired, {{0, announced}}, options);
    out.waits += choice.action == YieldAction::Wait;
    out.sidesteps += choice.action == YieldAction::Sidestep;
    out.holds += choice.action == YieldAction::Hold;
    p0 = announced.at(now + tick);
    p1 = choice.plan.at(now + tick);
    out.minDistance = std::min(out.minDistance, (p0 - p1).norm());
  }
  out.lowReached = (p1 - goal1).norm() < 1e-6;
  EXPECT_LT((p0 - goal0).norm(), 1e-6);
  return out;
}

TEST(Deconfliction, CrossingPairWaitsAndKeepsSeparation) {
  DeconflictionOptions options;
  // Both reach the crossing point (10, 10, 5) after 5 s.
  const Encounter e =
      fly(Vec3(0, 10, 5), Vec3(20, 10, 5), Vec3(10, 0, 5), Vec3(10, 20, 5), options);
  EXPECT_GE(e.minDistance, options.separation - 1e-6);
  EXPECT_TRUE(e.lowReached);
  EXPECT_GT(e.waits, 0);
  EXPECT_EQ(e.holds, 0);
}

TEST(Deconfliction, HeadOnPairSidestepsAndKeepsSeparation) {
  DeconflictionOptions options;
  const Encounter e = fly(Vec3(0, 0, 5), Vec3(40, 0, 5), Vec3(40, 0, 5), Vec3(0, 0, 5), options);
  EXPECT_GE(e.minDistance, options.separation - 1e-6);
  EXPECT_TRUE(e.lowReached);
  EXPECT_GT(e.sidesteps, 0);
  EXPECT_EQ(e.holds, 0);
  // Without deconfliction they would collide head-on.
  const TimedPath a = straightTo(0, Vec3(0, 0, 5), Vec3(40, 0, 5), 2.0, options);
  const TimedPath b = straightTo(0, Vec3(40, 0, 5), Vec3(0, 0, 5), 2.0, options);
  EXPECT_EQ(deconflict(1, 0.0, Vec3(40, 0, 5), b, {{0, a}}, options).action, YieldAction::Proceed);
}

TEST(Deconfliction, SidestepsHonourTheMapCheckAndFallBackToHold) {
  DeconflictionOptions options;
  // The priority robot flies through our position; no sidestep is allowed by the map.
  const TimedPath through = straightTo(0.0, Vec3(-5, 0, 5), Vec3(5, 0, 5), 2.0, options);
  const TimedPath stay = TimedPath::hold(0.0, Vec3(0, 0, 5));
  const auto nothing = [](const Vec3&, const Vec3&) { return false; };
  const DeconflictionResult blocked =
      deconflict(3, 0.0, Vec3(0, 0, 5), stay, {{1, through}}, options, nothing);
  EXPECT_EQ(blocked.action, YieldAction::Hold);
  // Only upward moves allowed: it climbs out of the way.
  const auto upOnly = [](const Vec3& a, const Vec3& b) { return b.z() > a.z(); };
  const DeconflictionResult up =
      deconflict(3, 0.0, Vec3(0, 0, 5), stay, {{1, through}}, options, upOnly);
  EXPECT_EQ(up.action, YieldAction::Sidestep);
  EXPECT_EQ(up.sidestepTarget, Vec3(0, 0, 8));
  // A lower-priority robot in the way is ignored.
  EXPECT_EQ(deconflict(0, 0.0, Vec3(0, 0, 5), stay, {{1, through}}, options).action,
            YieldAction::Proceed);
}

TEST(Deconfliction, TimedPathInterpolatesAndHolds) {
  const TimedPath path{1.0, 0.5, {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 2, 0)}};
  EXPECT_EQ(path.at(0.0), Vec3(0, 0, 0));
  EXPECT_EQ(path.at(1.25), Vec3(0.5, 0, 0));
  EXPECT_EQ(path.at(1.75), Vec3(1, 1, 0));
  EXPECT_EQ(path.at(9.0), Vec3(1, 2, 0));
  const TimedPath moving = TimedPath::constantVelocity(2.0, Vec3(0, 0, 0), Vec3(1, 0, 0), 3.0, 0.1);
  EXPECT_NEAR(moving.at(4.0).x(), 2.0, 1e-12);
  const Trajectory line({Vec3::Zero(), Vec3(10, 0, 0)}, TrajectoryLimits{});
  const TimedPath sampled = TimedPath::fromTrajectory(line, 5.0, 6.0, 2.0, 0.1);
  EXPECT_LT((sampled.at(7.0) - line.sample(2.0).position).norm(), 1e-12);
}

}  // namespace
}  // namespace coinspect::planning
