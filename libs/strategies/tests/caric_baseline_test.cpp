#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include "coinspect/strategies/builtin.h"
#include "coinspect/strategies/caric_baseline.h"
#include "coinspect/strategies/caric_baseline_plan.h"
#include "coinspect/testing/input_errors.h"
#include "test_boxes.h"

namespace coinspect::strategies {
namespace {

using test::makeBox;

using agent::Role;
using baseline::UnitStart;

// Two explorers far apart, four photographers: two beside each explorer.
std::vector<UnitStart> fleet() {
  return {{"gcs", Role::GroundStation, {0, 0, 0}}, {"e1", Role::Explorer, {0, 0, 0}},
          {"e2", Role::Explorer, {100, 0, 0}},     {"p1", Role::Photographer, {99, 2, 0}},
          {"p2", Role::Photographer, {1, 2, 0}},   {"p3", Role::Photographer, {2, 2, 0}},
          {"p4", Role::Photographer, {3, 2, 0}}};
}

TEST(CaricBaselinePlan, TeamsJoinTheNearestExplorerWithRoom) {
  const auto teams = baseline::formTeams(fleet());
  ASSERT_EQ(teams.size(), 2u);
  EXPECT_EQ(teams[0].explorer, 1);
  EXPECT_EQ(teams[1].explorer, 2);
  // p2 and p3 are nearest e1; p4 also is, but e1 is full (capacity 2), so it joins e2 with p1.
  EXPECT_EQ(teams[0].photographers, (std::vector<int>{4, 5}));
  EXPECT_EQ(teams[1].photographers, (std::vector<int>{3, 6}));
  // Without explorers each photographer is a team of its own.
  const auto alone = baseline::formTeams(
      {{"a", Role::Photographer, {0, 0, 0}}, {"b", Role::Photographer, {1, 0, 0}}});
  ASSERT_EQ(alone.size(), 2u);
  EXPECT_EQ(alone[1].explorer, -1);
}

TEST(CaricBaselinePlan, BoxesGoToTeamsInProportionAndNearTheirStart) {
  auto units = fleet();
  auto teams = baseline::formTeams(units);
  // Team 0 has 3 members, team 1 only 2: move p4 over to make it 3 + 2... p4 is already in
  // team 1 (3 members each). Drop p1 to get 3 and 2.
  teams[1].photographers = {6};
  const std::vector<BoxView> boxes{makeBox({0, 20, 10}, {10, 10, 20}),
                                   makeBox({100, 20, 10}, {10, 10, 20})};
  const auto assigned = baseline::assignBoxes(boxes, teams, units);
  ASSERT_EQ(assigned.size(), 2u);
  double work[2] = {0.0, 0.0};
  for (int t = 0; t < 2; ++t)
    for (const auto& box : assigned[t])
      work[t] += baseline::boxWorkload(box);
  // 3 : 2 of the total (one box is cut along its longest side, so the split is approximate).
  EXPECT_NEAR(work[0] / (work[0] + work[1]), 0.6, 0.08);
  // Each team starts with the box next to it.
  EXPECT_LT((assigned[0].front().center - Vec3(0, 20, 10)).norm(), 6.0);
  EXPECT_LT((assigned[1].front().center - Vec3(100, 20, 10)).norm(), 6.0);
}

TEST(CaricBaselinePlan, LayersSnakeAndDivideIntoBalancedRuns) {
  const std::vector<BoxView> boxes{makeBox({0, 0, 10}, {10, 10, 20}),
                                   makeBox({30, 0, 10}, {10, 10, 20})};
  const auto layers = baseline::layersOf(boxes, 5.0, 3.0, 7.0);
  ASSERT_EQ(layers.size(), 8u);
  EXPECT_NEAR(layers[0].z, 3.0, 1e-12);  // 2.5 raised to the floor
  EXPECT_NEAR(layers[3].z, 17.5, 1e-12);
  EXPECT_NEAR(layers[4].z, 17.5, 1e-12);  // the second box from the top down
  EXPECT_NEAR(layers[7].z, 3.0, 1e-12);
  const auto parts = baseline::divideLayers(layers, 3);
  ASSERT_EQ(parts.size(), 3u);
  size_t total = 0;
  for (const auto& part : parts) {
    EXPECT_GE(part.size(), 2u);
    EXPECT_LE(part.size(), 3u);
    total += part.size();
  }
  EXPECT_EQ(total, 8u);
  EXPECT_NEAR(parts[0].front().z, 3.0, 1e-12);  // consecutive runs, in order
}

TEST(CaricBaselinePlan, AFailedLayerIsTriedOnceMoreAfterTheOthers) {
  const std::vector<BoxView> boxes{makeBox({0, 0, 10}, {10, 10, 20})};
  auto layers = baseline::layersOf(boxes, 10.0, 3.0, 7.0);
  ASSERT_EQ(layers.size(), 2u);
  const double firstZ = layers[0].z;
  baseline::requeueFailedLayer(layers, 0);
  ASSERT_EQ(layers.size(), 3u);
  EXPECT_EQ(layers[2].z, firstZ);
  EXPECT_TRUE(layers[2].retry);
  EXPECT_FALSE(layers[0].retry);
  baseline::requeueFailedLayer(layers, 2);  // its second try failed too: dropped
  EXPECT_EQ(layers.size(), 3u);
}

TEST(CaricBaselineOptions, ReadsKeysStrictly) {
  const auto config = Config::fromText(
      "[caric-baseline]\nmax_speed = 1.5\nunknown_space = blocked\nreturn_home = false\n",
      "run.ini");
  const auto options = CaricBaselineOptions::read(config);
  EXPECT_DOUBLE_EQ(options.maxSpeed, 1.5);
  EXPECT_EQ(options.unknownSpace, runtime::UnknownSpace::Blocked);
  EXPECT_FALSE(options.returnHome);
  config.requireAllKeysUsed();

  for (const auto& [text, key] : std::vector<std::pair<std::string, std::string>>{
           {"max_speed = 0", "max_speed"},
           {"unknown_space = maybe", "unknown_space"},
           {"rate = 5", "rate"},
           {"grid_resolution = x", "grid_resolution"},
           {"explorer_sweep_every = -1", "explorer_sweep_every"}}) {
    const auto bad = Config::fromText("[caric-baseline]\n" + text + "\n", "bad.ini");
    const auto message = testing::messageOf([&] { CaricBaselineOptions::read(bad); });
    EXPECT_MENTIONS(message, "bad.ini");
    EXPECT_MENTIONS(message, key);
  }
}

TEST(CaricBaseline, IsRegisteredAndGroundStationsStayPut) {
  agent::StrategyRegistry registry;
  registerBuiltinStrategies(registry);
  ASSERT_TRUE(registry.has("caric-baseline"));
  const auto config = Config::fromText("", "run.ini");
  agent::StrategyContext context{config,
                                 "caric-baseline",
                                 "gcs",
                                 Role::GroundStation,
                                 0,
                                 1,
                                 {{"gcs", Role::GroundStation}},
                                 {},
                                 0.0};
  auto strategy = registry.create("caric-baseline", context);
  EXPECT_DOUBLE_EQ(strategy->decisionRate(), 10.0);
  agent::AgentView view;
  view.role = Role::GroundStation;
  const auto command = strategy->decide(view);
  EXPECT_FALSE(command.setpoint.has_value());
  EXPECT_FALSE(command.gimbal.has_value());
}

}  // namespace
}  // namespace coinspect::strategies
