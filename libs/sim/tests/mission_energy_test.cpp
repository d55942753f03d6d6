// [energy]: explorers' batteries drain while airborne, charge near a live ground station, and a
// UAV whose battery is empty fails.
#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <memory>

#include "coinspect/sim/mission.h"
#include "coinspect/testing/input_errors.h"
#include "sim_scenes.h"

namespace coinspect::sim {
namespace {

// What the units saw: their battery levels over time and their fleet's battery specs.
struct Seen {
  std::map<std::string, std::vector<double>> levels;
  std::vector<agent::BatterySpec> fleet;
};

// "a" hovers 8 m from the station; "b" flies 4 m out, then to 1.8 m from the station at 1.5 s.
class Scripted : public agent::Strategy {
 public:
  Scripted(std::string name, Seen& seen) : name_(std::move(name)), seen_(seen) {}
  double decisionRate() const override { return 10.0; }
  agent::AgentCommand decide(const agent::AgentView& view) override {
    agent::AgentCommand command;
    if (name_ == "gcs") return command;
    seen_.levels[name_].push_back(view.energy);
    agent::AgentSetpoint setpoint;
    if (name_ == "a")
      setpoint.position = agent::Vec3(0, -8, 4);
    else
      setpoint.position = view.time < 1.5 ? agent::Vec3(0, 4, 4) : agent::Vec3(0, 1.5, 2);
    command.setpoint = setpoint;
    return command;
  }

 private:
  std::string name_;
  Seen& seen_;
};

agent::StrategyRegistry scripted(Seen& seen) {
  agent::StrategyRegistry registry;
  registry.registerStrategy("scripted", [&seen](const agent::StrategyContext& context) {
    seen.fleet.clear();
    for (const auto& member : context.fleet)
      seen.fleet.push_back(member.battery);
    return std::make_unique<Scripted>(context.unitName, seen);
  });
  return registry;
}

world::Scenario explorersScene() {
  auto scenario = testing::wallScenario({{"a", -8.0}, {"b", 4.0}});
  for (auto& unit : scenario.fleet)
    if (unit.role == world::UnitRole::Photographer) unit.role = world::UnitRole::Explorer;
  return scenario;
}

const std::string kEnergyMission =
    "[mission]\nexplorer_lidar = none\n[strategy]\nname = scripted\n"
    "[energy]\ncapacity = 10\ncharge_time = 4\nstart_level = 0.5\n";

TEST(MissionEnergy, DrainsInFlightChargesNearTheStationAndFailsWhenEmpty) {
  Seen seen;
  const auto registry = scripted(seen);
  const auto config = Config::fromText(kEnergyMission, "energy.ini");
  Mission mission(explorersScene(), config, registry);
  config.requireAllKeysUsed();
  mission.runUntil(15.0);
  const auto summary = mission.summary();
  ASSERT_TRUE(summary.started);

  // The fleet knows every explorer's battery; the station has none.
  ASSERT_EQ(seen.fleet.size(), 3u);
  EXPECT_FALSE(seen.fleet[0].limited());
  EXPECT_DOUBLE_EQ(seen.fleet[1].capacity, 10.0);
  EXPECT_DOUBLE_EQ(seen.fleet[2].chargeTime, 4.0);
  EXPECT_DOUBLE_EQ(seen.fleet[2].chargeRange, 3.0);

  // "a" never comes near the station: half of a 10 s battery lasts 5 s of flight.
  const size_t a = mission.unitIndex("a"), b = mission.unitIndex("b");
  EXPECT_FALSE(mission.unitAlive(a));
  const auto& events = mission.events();
  const auto death = std::find_if(events.begin(), events.end(), [](const MissionEvent& e) {
    return e.kind == "death" && e.unit == "a";
  });
  ASSERT_NE(death, events.end());
  EXPECT_EQ(death->detail, "battery empty");
  EXPECT_GT(death->time, summary.startTime + 4.9);
  EXPECT_LT(death->time, summary.startTime + 5.6);  // on the ground for a moment at the start
  const auto& aLevels = seen.levels.at("a");
  EXPECT_DOUBLE_EQ(aLevels.front(), 0.5);
  EXPECT_TRUE(std::is_sorted(aLevels.rbegin(), aLevels.rend()));  // never rises
  EXPECT_DOUBLE_EQ(*summary.units[a].lowestEnergy, 0.0);

  // "b" drains on its way out and back, then charges at 0.25 per s to full and stays full.
  EXPECT_TRUE(mission.unitAlive(b));
  const auto& bLevels = seen.levels.at("b");
  const double lowest = *std::min_element(bLevels.begin(), bLevels.end());
  EXPECT_GT(lowest, 0.1);
  EXPECT_LT(lowest, 0.4);
  EXPECT_DOUBLE_EQ(bLevels.back(), 1.0);
  EXPECT_NEAR(*summary.units[b].lowestEnergy, lowest, 0.02);
  EXPECT_NEAR(summary.units[b].chargedFor, 4.0 * (1.0 - lowest), 0.1);
  const auto charge = [&](const std::string& kind) {
    return std::count_if(events.begin(), events.end(),
                         [&](const MissionEvent& e) { return e.kind == kind && e.unit == "b"; });
  };
  EXPECT_EQ(charge("charge-start"), 1);
  EXPECT_EQ(charge("charge-end"), 1);
  EXPECT_FALSE(summary.units[0].lowestEnergy);  // the station has no battery
}

TEST(MissionEnergy, BadKeysAndAFleetWithoutAStationAreNamed) {
  Seen seen;
  const auto registry = scripted(seen);
  const auto build = [&](const std::string& energy, world::Scenario scene) {
    const auto config = Config::fromText(
        "[mission]\nexplorer_lidar = none\n[strategy]\nname = scripted\n[energy]\n" + energy,
        "energy.ini");
    Mission mission(std::move(scene), config, registry);
  };
  const auto messageFor = [&](const std::string& energy) {
    return coinspect::testing::messageOf([&] { build(energy, explorersScene()); });
  };
  EXPECT_MENTIONS(messageFor("charge_time = 4\n"), "[energy] capacity");
  EXPECT_MENTIONS(messageFor("capacity = -1\ncharge_time = 4\n"), "[energy] capacity");
  EXPECT_MENTIONS(messageFor("capacity = 10\n"), "[energy] charge_time");
  EXPECT_MENTIONS(messageFor("capacity = 10\ncharge_time = nan\n"), "[energy] charge_time");
  EXPECT_MENTIONS(messageFor("capacity = 10\ncharge_time = 4\ncharge_range = 0\n"),
                  "[energy] charge_range");
  EXPECT_MENTIONS(messageFor("capacity = 10\ncharge_time = 4\nstart_level = 1.5\n"),
                  "[energy] start_level");
  auto noStation = explorersScene();
  noStation.fleet.erase(noStation.fleet.begin());
  const auto message =
      coinspect::testing::messageOf([&] { build("capacity = 10\ncharge_time = 4\n", noStation); });
  EXPECT_MENTIONS(message, "[energy]");
  EXPECT_MENTIONS(message, "no ground station");
}

}  // namespace
}  // namespace coinspect::sim
