#include "coinspect/sim/mission.h"

#include <gtest/gtest.h>

#include <algorithm>

#include "coinspect/strategies/builtin.h"
#include "coinspect/testing/input_errors.h"
#include "sim_scenes.h"

namespace coinspect::sim {
namespace {

using testing::wallScenario;

agent::StrategyRegistry builtins() {
  agent::StrategyRegistry registry;
  strategies::registerBuiltinStrategies(registry);
  return registry;
}

const std::string kMission = "[mission]\nexplorer_lidar = none\n[strategy]\nname = demo-paths\n";

bool hasEvent(const Mission& mission, const std::string& kind, const std::string& unit,
              const std::string& detail = "") {
  const auto& events = mission.events();
  return std::any_of(events.begin(), events.end(), [&](const MissionEvent& e) {
    return e.kind == kind && e.unit == unit && e.detail.find(detail) != std::string::npos;
  });
}

TEST(Mission, TwoUavsFlownIntoEachOtherBothDie) {
  // a and b swap places at 3 m height: they meet halfway.
  const auto config = Config::fromText(kMission +
                                           "[demo-paths.a]\nwaypoints = 0 -3 3; 0 3 3\n"
                                           "[demo-paths.b]\nwaypoints = 0 3 3; 0 -3 3\n",
                                       "collide.ini");
  const auto registry = builtins();
  Mission mission(wallScenario({{"a", -3.0}, {"b", 3.0}}), config, registry);
  config.requireAllKeysUsed();
  mission.runUntil(8.0);
  const size_t a = mission.unitIndex("a"), b = mission.unitIndex("b");
  EXPECT_FALSE(mission.unitAlive(a));
  EXPECT_FALSE(mission.unitAlive(b));
  EXPECT_TRUE(hasEvent(mission, "collision", "a", "b"));
  EXPECT_TRUE(hasEvent(mission, "death", "a", "collision with b"));
  EXPECT_TRUE(hasEvent(mission, "death", "b", "collision with a"));
  // They met near y = 0 and then fell to the ground (the motors are off), drifting on with
  // their speed at the collision (about 1.5 m/s for the 0.8 s fall from 3 m).
  EXPECT_LT(std::abs(mission.unitState(a).position.y()), 2.0);
  EXPECT_LT(mission.unitState(a).position.z(), 0.1);
  const auto summary = mission.summary();
  EXPECT_EQ(summary.collisions, 2u);
  EXPECT_EQ(summary.deaths, 2u);
}

TEST(Mission, UavFlownIntoAWallDiesAndKeepsItsScore) {
  // Straight at the wall (x = 10) at 5 m height, camera on the wall's centre.
  const auto config =
      Config::fromText(kMission +
                           "[demo-paths.a]\nwaypoints = 0 0 5; 15 0 5\nspeed = 1.5\n"
                           "gimbal_target = 10 0 5\n",
                       "wall.ini");
  const auto registry = builtins();
  Mission mission(wallScenario({{"a", 0.0}}), config, registry);
  const size_t a = mission.unitIndex("a");
  while (mission.unitAlive(a) && mission.time() < 15.0)
    mission.step();
  ASSERT_FALSE(mission.unitAlive(a));
  EXPECT_TRUE(hasEvent(mission, "death", "a", "collision with a surface"));
  // It died at the wall, one collision radius (0.32 m) or less before its face.
  EXPECT_GT(mission.unitState(a).position.x(), 9.6);
  EXPECT_LT(mission.unitState(a).position.x(), 10.0);
  const double earned = mission.unitOwnScore(a);
  EXPECT_GT(earned, 1.0);
  // The ground station at (0, 0, 1) saw it all the way: the tally holds the score too.
  EXPECT_GT(mission.gcsScore(), 1.0);
  mission.runUntil(18.0);
  EXPECT_GE(mission.unitOwnScore(a), earned);
  EXPECT_EQ(mission.summary().collisions, 1u);
}

TEST(Mission, LandingIsNotACollision) {
  const auto config = Config::fromText(
      kMission + "[demo-paths.a]\nwaypoints = 0 0 3; 2 0 3; 2 0 0\nspeed = 1.5\n", "land.ini");
  const auto registry = builtins();
  Mission mission(wallScenario({{"a", 0.0}}), config, registry);
  mission.runUntil(12.0);
  const size_t a = mission.unitIndex("a");
  EXPECT_TRUE(mission.unitAlive(a));
  EXPECT_NEAR(mission.unitState(a).position.z(), 0.0, 0.05);
  EXPECT_NEAR(mission.unitState(a).position.x(), 2.0, 0.2);
  EXPECT_EQ(mission.summary().collisions, 0u);
}

// Waits on the ground until t = 2 s, then climbs to 3 m.
class LateClimb : public agent::Strategy {
 public:
  agent::AgentCommand decide(const agent::AgentView& view) override {
    if (view.time < 2.0) {
      EXPECT_FALSE(view.started);
      EXPECT_EQ(view.missionTime, 0.0);
      return {};
    }
    agent::AgentCommand command;
    agent::AgentSetpoint setpoint;
    setpoint.position = agent::Vec3(0, 0, 3);
    command.setpoint = setpoint;
    return command;
  }
};

TEST(Mission, ClockStartsAtTakeOffAndTheBudgetCountsFromThere) {
  agent::StrategyRegistry registry;
  registry.registerStrategy(
      "late", [](const agent::StrategyContext&) { return std::make_unique<LateClimb>(); });
  const auto config = Config::fromText(
      "[mission]\nexplorer_lidar = none\nbudget = 3\n[strategy]\nname = late\n", "late.ini");
  Mission mission(wallScenario({{"a", 0.0}}), config, registry);
  mission.run();
  const auto summary = mission.summary();
  ASSERT_TRUE(summary.started);
  // Commanded at 2 s; at 4 rad/s it needs a few tenths of a second to pass 0.1 m and 0.1 m/s.
  EXPECT_GT(summary.startTime, 2.0);
  EXPECT_LT(summary.startTime, 3.0);
  EXPECT_NEAR(summary.missionTime, 3.0, 0.0026);
  EXPECT_NEAR(summary.simTime, summary.startTime + 3.0, 0.0026);
  EXPECT_TRUE(hasEvent(mission, "mission-start", "a"));
  EXPECT_TRUE(hasEvent(mission, "mission-end", ""));
}

TEST(Mission, FaultKillsTheUnitAtItsTime) {
  const auto config = Config::fromText(
      kMission + "[demo-paths.a]\nwaypoints = 0 0 4\n[fault.1]\nunit = a\nat = 3\n", "fault.ini");
  const auto registry = builtins();
  Mission mission(wallScenario({{"a", 0.0}}), config, registry);
  mission.runUntil(2.9);
  const size_t a = mission.unitIndex("a");
  EXPECT_TRUE(mission.unitAlive(a));
  EXPECT_GT(mission.unitState(a).position.z(), 3.0);
  mission.runUntil(6.0);
  EXPECT_FALSE(mission.unitAlive(a));
  const auto& events = mission.events();
  const auto death = std::find_if(events.begin(), events.end(),
                                  [](const MissionEvent& e) { return e.kind == "death"; });
  ASSERT_NE(death, events.end());
  EXPECT_DOUBLE_EQ(death->time, 3.0);
  EXPECT_NE(death->detail.find("fault"), std::string::npos);
  // Dead, it fell: motors off.
  EXPECT_LT(mission.unitState(a).position.z(), 0.1);
  EXPECT_EQ(mission.summary().collisions, 0u);
}

double gcsScoreAfter(const std::string& extra) {
  const auto config = Config::fromText(kMission +
                                           "[demo-paths.a]\nwaypoints = 0 0 5; 3 0 5\n"
                                           "gimbal_target = 10 0 5\n" +
                                           extra,
                                       "blackout.ini");
  const auto registry = builtins();
  Mission mission(wallScenario({{"a", 0.0}}), config, registry);
  mission.runUntil(8.0);
  EXPECT_GT(mission.unitOwnScore(1), 1.0);
  return mission.gcsScore();
}

TEST(Mission, LinkBlackoutBlocksTheGroundStationMerge) {
  const double open = gcsScoreAfter("");
  EXPECT_GT(open, 1.0);
  // All links down for the whole flight: the ground station never hears of the captures.
  EXPECT_EQ(gcsScoreAfter("[blackout.1]\nfrom = 0\nto = 100\n"), 0.0);
  // Only a's links down: the same.
  EXPECT_EQ(gcsScoreAfter("[blackout.1]\nfrom = 0\nto = 100\nunits = a\n"), 0.0);
  // Links back from 7 s: the tally catches up with a's whole log.
  EXPECT_EQ(gcsScoreAfter("[blackout.1]\nfrom = 0\nto = 7\n"), open);
}

TEST(Mission, SameSeedGivesTheSameTrajectoryBitForBit) {
  const auto run = [] {
    const auto config = Config::fromText(kMission +
                                             "[demo-paths.a]\nwaypoints = 0 -3 4; 6 -2 6\n"
                                             "gimbal_target = 10 0 5\n"
                                             "[demo-paths.b]\nwaypoints = 0 3 2; 6 2 5\n"
                                             "gimbal_target = 10 0 5\nyaw = travel\n",
                                         "same.ini");
    const auto registry = builtins();
    Mission mission(wallScenario({{"a", -3.0}, {"b", 3.0}}), config, registry, 7);
    mission.runUntil(10.0);
    return std::make_pair(mission.stateDigest(), mission.summary());
  };
  const auto [digest1, first] = run();
  const auto [digest2, second] = run();
  EXPECT_EQ(digest1, digest2);
  EXPECT_EQ(first.score, second.score);
  EXPECT_EQ(first.detected, second.detected);
  ASSERT_EQ(first.units.size(), second.units.size());
  for (size_t i = 0; i < first.units.size(); ++i) {
    EXPECT_EQ(first.units[i].distanceFlown, second.units[i].distanceFlown);
    EXPECT_EQ(first.units[i].ownScore, second.units[i].ownScore);
    EXPECT_EQ(first.units[i].captures, second.units[i].captures);
  }
  EXPECT_EQ(first.startTime, second.startTime);
  EXPECT_GT(first.score, 0.0);
}

TEST(Mission, UnknownUnitsAndStrategiesAreNamed) {
  const auto registry = builtins();
  auto config = Config::fromText(kMission + "[fault.x]\nunit = nobody\nat = 1\n", "bad.ini");
  auto message = coinspect::testing::messageOf([&] {
    Mission(wallScenario({{"a", 0.0}}), config, registry);
  });
  EXPECT_MENTIONS(message, "nobody");
  config = Config::fromText("[mission]\n[strategy]\nname = teleport\n", "bad.ini");
  message = coinspect::testing::messageOf([&] {
    Mission(wallScenario({{"a", 0.0}}), config, registry);
  });
  EXPECT_MENTIONS(message, "teleport");
  EXPECT_MENTIONS(message, "demo-paths");
}

}  // namespace
}  // namespace coinspect::sim
