// Ground stations as ground vehicles, and where dead UAVs come to rest.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "coinspect/sim/mission.h"
#include "coinspect/strategies/builtin.h"
#include "sim_scenes.h"

namespace coinspect::sim {
namespace {

using testing::boxMesh;
using testing::wallScenario;

agent::StrategyRegistry builtins() {
  agent::StrategyRegistry registry;
  strategies::registerBuiltinStrategies(registry);
  return registry;
}

const std::string kMission = "[mission]\nexplorer_lidar = none\n[strategy]\nname = demo-paths\n";

// The wall scene with its ground station moved onto the ground at the origin.
world::Scenario groundStationScene() {
  auto scenario = wallScenario({});
  scenario.fleet.at(0).startPosition = world::Vec3(0, 0, 0);
  return scenario;
}

TEST(MissionGroundStation, DrivesToItsWaypointAtGcsSpeed) {
  // demo-paths moves the gcs's reference at 2 m/s, faster than the gcs may drive, so the gcs
  // drives at 1 m/s all the way. Its first decision (t = 0) targets where it stands; the
  // reference has moved at the second (t = 0.1 s): it arrives 10 m further at t = 10.1 s.
  const auto config = Config::fromText(
      "[mission]\nexplorer_lidar = none\ngcs_speed = 1\n[strategy]\nname = demo-paths\n"
      "[demo-paths.gcs]\nwaypoints = -10 0 0\n",
      "gcs.ini");
  const auto registry = builtins();
  Mission mission(groundStationScene(), config, registry);
  config.requireAllKeysUsed();
  const size_t gcs = mission.unitIndex("gcs");
  const world::Vec3 waypoint(-10, 0, 0);
  auto last = mission.unitState(gcs);
  while (mission.time() < 10.0 - 1e-9) {
    mission.step();
    const auto state = mission.unitState(gcs);
    EXPECT_LE((state.position - last.position).norm(), 1.0 * (state.time - last.time) + 1e-9);
    EXPECT_LE(state.velocity.norm(), 1.0 + 1e-9);
    EXPECT_EQ(state.position.z(), 0.0);
    last = state;
  }
  // Not there before 10.1 s (the state is that of the last vehicle update, at most 10 ms old).
  const auto before = mission.unitState(gcs);
  EXPECT_GE(before.time, 9.99 - 1e-9);
  EXPECT_NEAR((before.position - waypoint).norm(), 10.1 - before.time, 1e-6);
  mission.runUntil(10.2);
  EXPECT_NEAR((mission.unitState(gcs).position - waypoint).norm(), 0.0, 1e-9);
}

TEST(MissionGroundStation, StopsAtAWallInsteadOfDrivingThroughIt) {
  // The wall occupies 10 <= x <= 11; the gcs (0.5 m up, clear of the ground plane) is sent to
  // x = 20 straight through it.
  const auto config = Config::fromText(
      "[mission]\nexplorer_lidar = none\ngcs_speed = 1\n[strategy]\nname = demo-paths\n"
      "[demo-paths.gcs]\nwaypoints = 20 0 0.5\n",
      "gcs.ini");
  const auto registry = builtins();
  auto scenario = wallScenario({});
  scenario.fleet.at(0).startPosition = world::Vec3(0, 0, 0.5);
  Mission mission(std::move(scenario), config, registry);
  mission.runUntil(15.0);
  const auto state = mission.unitState(mission.unitIndex("gcs"));
  EXPECT_LT(state.position.x(), 10.0);
  EXPECT_GT(state.position.x(), 9.9);  // it got there (1 m/s for 15 s) and no further
  EXPECT_EQ(state.velocity, world::Vec3::Zero());
}

TEST(MissionGroundStation, StaticByDefault) {
  const auto config =
      Config::fromText(kMission + "[demo-paths.gcs]\nwaypoints = -10 0 0\n", "gcs.ini");
  const auto registry = builtins();
  Mission mission(groundStationScene(), config, registry);
  mission.runUntil(3.0);
  EXPECT_EQ(mission.unitState(mission.unitIndex("gcs")).position, world::Vec3(0, 0, 0));
}

// The gcs: a non-finite setpoint first, then a target 10 m to -x (z 5: ignored). A UAV: records
// where it sees the gcs among its neighbours.
struct Sighting {
  double time = 0.0;
  bool seen = false;
  world::Vec3 position = world::Vec3::Zero();
};

class Probe : public agent::Strategy {
 public:
  explicit Probe(std::vector<Sighting>* sightings) : sightings_(sightings) {}
  agent::AgentCommand decide(const agent::AgentView& view) override {
    agent::AgentCommand command;
    if (view.role == agent::Role::GroundStation) {
      agent::AgentSetpoint setpoint;
      setpoint.position = view.time < 0.05
                              ? agent::Vec3(std::numeric_limits<double>::quiet_NaN(), 0, 0)
                              : agent::Vec3(-10, 0, 5);
      command.setpoint = setpoint;
      return command;
    }
    Sighting sighting{view.time, false, world::Vec3::Zero()};
    for (const auto& neighbour : view.neighbours)
      if (neighbour.name == "gcs") sighting = {view.time, true, neighbour.odometry.position};
    sightings_->push_back(sighting);
    return command;  // no setpoint: the UAV idles where it starts
  }

 private:
  std::vector<Sighting>* sightings_;
};

TEST(MissionGroundStation, LinksAndNeighbourOdometryFollowIt) {
  std::vector<Sighting> sightings;
  agent::StrategyRegistry registry;
  registry.registerStrategy(
      "probe", [&](const agent::StrategyContext&) { return std::make_unique<Probe>(&sightings); });
  const auto config = Config::fromText(
      "[mission]\nexplorer_lidar = none\nlinks = range\nlink_range = 5\ngcs_speed = 1\n"
      "[strategy]\nname = probe\n",
      "probe.ini");
  // The gcs on a 1 m mast at the origin, the UAV idling 2 m to +x at the same height.
  auto scenario = wallScenario({{"a", 0.0}});
  scenario.fleet.at(1).startPosition = world::Vec3(2, 0, 1);
  Mission mission(std::move(scenario), config, registry);
  mission.runUntil(4.0);
  // The NaN target was rejected and counted; the gcs drives from t = 0.1 s at 1 m/s, so it is
  // 2 + (t - 0.1) m from the UAV: in range up to t = 3.1 s, out of it after.
  EXPECT_EQ(mission.summary().units.at(mission.unitIndex("gcs")).rejectedCommands, 1);
  ASSERT_EQ(sightings.size(), 40u);
  for (const auto& s : sightings) {
    if (s.time < 3.05) {
      ASSERT_TRUE(s.seen) << "t = " << s.time;
      EXPECT_NEAR(s.position.x(), -std::max(0.0, s.time - 0.1), 1e-6) << "t = " << s.time;
      EXPECT_EQ(s.position.z(), 1.0);
    } else if (s.time > 3.15) {
      EXPECT_FALSE(s.seen) << "t = " << s.time;
    }
  }
}

TEST(MissionDeadUav, FallsOntoTheRoofBelowIt) {
  // A 4 m high building under a UAV hovering at 7 m (it starts there: an idle vehicle stays
  // where it is put until its first command). The fault at 1.5 s stops its motors; it falls
  // 3 m (0.78 s) and must lie on the roof, not on the ground inside the building.
  auto scenario = wallScenario({{"a", 0.0}});
  scenario.meshes.push_back(boxMesh({-15, 5, 0}, {-5, 15, 4}));
  scenario.fleet.at(1).startPosition = world::Vec3(-10, 10, 7);
  const auto config = Config::fromText(
      kMission + "[demo-paths.a]\nwaypoints = -10 10 7\n[fault.1]\nunit = a\nat = 1.5\n",
      "roof.ini");
  const auto registry = builtins();
  Mission mission(std::move(scenario), config, registry);
  const size_t a = mission.unitIndex("a");
  mission.runUntil(1.4);
  ASSERT_TRUE(mission.unitAlive(a));
  EXPECT_NEAR(mission.unitState(a).position.z(), 7.0, 0.05);
  mission.runUntil(3.0);
  EXPECT_FALSE(mission.unitAlive(a));
  const auto state = mission.unitState(a);
  EXPECT_NEAR(state.position.z(), 4.0, 0.03);
  EXPECT_EQ(state.velocity, world::Vec3::Zero());
  EXPECT_EQ(mission.summary().collisions, 0u);
}

}  // namespace
}  // namespace coinspect::sim
