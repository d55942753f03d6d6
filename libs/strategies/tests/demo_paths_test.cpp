#include <gtest/gtest.h>

#include <cmath>

#include "coinspect/strategies/builtin.h"
#include "coinspect/strategies/demo_paths.h"
#include "coinspect/testing/input_errors.h"

namespace coinspect::strategies {
namespace {

constexpr double kDegree = M_PI / 180.0;

std::unique_ptr<agent::Strategy> makeStrategy(const std::string& text, const std::string& unit,
                                              bool allKeysUsed = true) {
  agent::StrategyRegistry registry;
  registerBuiltinStrategies(registry);
  const auto config = Config::fromText(text, "run.ini");
  const agent::StrategyContext context{config, "demo-paths", unit, agent::Role::Photographer, 0, 1,
                                       {},     {},           0.0};
  auto strategy = registry.create("demo-paths", context);
  if (allKeysUsed) config.requireAllKeysUsed();
  return strategy;
}

// A perfect vehicle: it is always exactly where the last setpoint asked.
struct PerfectFlight {
  agent::AgentView view;
  agent::AgentCommand last;
  void step(agent::Strategy& strategy, double dt) {
    last = strategy.decide(view);
    ASSERT_TRUE(last.setpoint.has_value());
    view.odometry.position = last.setpoint->position;
    view.odometry.yaw = last.setpoint->yaw;
    view.time += dt;
  }
};

TEST(DemoPaths, TakesOffThenVisitsTheWaypointsAndHoversAtTheEnd) {
  // Start at the origin; climb 5 m, fly 10 m along x, then 10 m along y: 25 m at 2 m/s = 12.5 s.
  auto strategy =
      makeStrategy("[demo-paths.a]\nwaypoints = 10 0 5; 10 10 5\nspeed = 2\nyaw = travel\n", "a");
  EXPECT_DOUBLE_EQ(strategy->decisionRate(), 10.0);
  PerfectFlight flight;
  flight.step(*strategy, 0.1);
  // First decision: the reference point is still at the start, climbing at 2 m/s.
  EXPECT_NEAR((flight.last.setpoint->position - Vec3(0, 0, 0)).norm(), 0.0, 1e-12);
  EXPECT_NEAR((flight.last.setpoint->velocity - Vec3(0, 0, 2)).norm(), 0.0, 1e-12);
  for (int i = 0; i < 29; ++i)
    flight.step(*strategy, 0.1);
  // Decision at t = 2.9 s: 5 m up, then 0.8 m along x, heading +x.
  EXPECT_NEAR((flight.last.setpoint->position - Vec3(0.8, 0, 5)).norm(), 0.0, 1e-9);
  EXPECT_NEAR((flight.last.setpoint->velocity - Vec3(2, 0, 0)).norm(), 0.0, 1e-12);
  EXPECT_NEAR(flight.last.setpoint->yaw, 0.0, 1e-12);
  for (int i = 0; i < 50; ++i)
    flight.step(*strategy, 0.1);
  // t = 7.9 s: 15.8 m travelled, 0.8 m along the +y leg, facing +y.
  EXPECT_NEAR((flight.last.setpoint->position - Vec3(10, 0.8, 5)).norm(), 0.0, 1e-9);
  EXPECT_NEAR(flight.last.setpoint->yaw, M_PI / 2, 1e-12);
  for (int i = 0; i < 100; ++i)
    flight.step(*strategy, 0.1);
  EXPECT_NEAR((flight.last.setpoint->position - Vec3(10, 10, 5)).norm(), 0.0, 1e-9);
  EXPECT_EQ(flight.last.setpoint->velocity, Vec3::Zero());
  // No target: the gimbal holds the configured pitch (0 by default).
  ASSERT_TRUE(flight.last.gimbal.has_value());
  EXPECT_EQ(flight.last.gimbal->pitch, 0.0);
}

TEST(DemoPaths, WaitsForAVehicleThatLagsBehind) {
  auto strategy = makeStrategy("[demo-paths.a]\nwaypoints = 100 0 0\nspeed = 2\n", "a");
  agent::AgentView view;  // the vehicle never moves from the origin
  agent::AgentCommand command;
  for (int i = 0; i < 100; ++i, view.time += 0.1)
    command = strategy->decide(view);
  // The reference point advances 0.2 m per decision while it is within max(2, 1.5 * 2) = 3 m:
  // it stops one step past 3 m at most (3.0 or 3.2 m, depending on rounding at the bound).
  EXPECT_GE(command.setpoint->position.x(), 3.0 - 1e-9);
  EXPECT_LE(command.setpoint->position.x(), 3.2 + 1e-9);
}

TEST(DemoPaths, AimsTheGimbalAtTheTarget) {
  // Camera 10 m above the ground, target 5 m ahead on the ground: pitch atan(10 / 5) down.
  auto strategy = makeStrategy(
      "[demo-paths.a]\nwaypoints = 0 0 10\ngimbal_target = 5 0 0\ncamera_offset = 0 0 0\n", "a");
  agent::AgentView view;
  view.odometry.position = Vec3(0, 0, 10);
  view.gimbal.pitchMax = 80 * kDegree;
  view.gimbal.yawMax = 90 * kDegree;
  const auto command = strategy->decide(view);
  ASSERT_TRUE(command.gimbal.has_value());
  EXPECT_EQ(command.gimbal->mode, agent::GimbalCommand::Mode::Angles);
  EXPECT_NEAR(command.gimbal->pitch, std::atan(2.0), 1e-12);
  EXPECT_NEAR(command.gimbal->yaw, 0.0, 1e-12);
  EXPECT_NEAR(command.setpoint->yaw, 0.0, 1e-12);  // yaw = target (default) faces it

  // Limits respected: a pitch limit of 30 deg clamps the 63.4 deg aim.
  view.gimbal.pitchMax = 30 * kDegree;
  EXPECT_NEAR(strategy->decide(view).gimbal->pitch, 30 * kDegree, 1e-12);
}

TEST(DemoPaths, AimAnglesByHand) {
  // Body facing +y (yaw 90 deg); a target straight behind along -x is to the body's left:
  // stabilizer-frame direction (0, 10, 0), gimbal yaw +90 deg, pitch 0.
  auto aim = aimGimbal(Vec3::Zero(), M_PI / 2, Vec3(-10, 0, 0));
  EXPECT_NEAR(aim.yaw, M_PI / 2, 1e-12);
  EXPECT_NEAR(aim.pitch, 0.0, 1e-12);
  // Up and ahead: 3-4-5 triangle, looking up is negative pitch.
  aim = aimGimbal(Vec3(1, 1, 1), 0.0, Vec3(5, 1, 4));
  EXPECT_NEAR(aim.pitch, -std::atan2(3.0, 4.0), 1e-12);
  EXPECT_NEAR(aim.yaw, 0.0, 1e-12);
}

TEST(DemoPaths, UnitWithoutSectionDoesNothingAndBadValuesAreNamed) {
  auto idle = makeStrategy("[demo-paths.a]\nwaypoints = 1 2 3\n", "b", false);
  const auto command = idle->decide(agent::AgentView{});
  EXPECT_FALSE(command.setpoint.has_value());
  EXPECT_FALSE(command.gimbal.has_value());
  auto message =
      testing::messageOf([] { makeStrategy("[demo-paths.a]\nwaypoints = 1 2; 3 4 5\n", "a"); });
  EXPECT_MENTIONS(message, "[demo-paths.a] waypoints");
  message = testing::messageOf(
      [] { makeStrategy("[demo-paths.a]\nwaypoints = 1 2 3\nspeed = -1\n", "a"); });
  EXPECT_MENTIONS(message, "speed");
  message = testing::messageOf(
      [] { makeStrategy("[demo-paths.a]\nwaypoints = 1 2 3\nyaw = sideways\n", "a"); });
  EXPECT_MENTIONS(message, "sideways");
}

}  // namespace
}  // namespace coinspect::strategies
