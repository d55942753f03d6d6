#include "coinspect/strategies/kios/kios_strategy.h"

#include <gtest/gtest.h>

#include <utility>

#include "coinspect/strategies/builtin.h"
#include "coinspect/testing/input_errors.h"

namespace coinspect::strategies::kios {
namespace {

TEST(KiosOptions, ReadsKeysStrictly) {
  const auto config = Config::fromText(
      "[kios]\nexplore_standoff = 12\nexplore_heights = 3\nview_distance = 0.8\n"
      "stops_per_plan = 5\nmtsp_seed = 7\nbroadcast_visited = false\nmtsp_starts = positions\n",
      "run.ini");
  const auto options = KiosOptions::read(config);
  EXPECT_DOUBLE_EQ(options.exploreStandoff, 12.0);
  EXPECT_EQ(options.exploreHeights, 3);
  EXPECT_DOUBLE_EQ(options.viewDistance, 0.8);
  EXPECT_EQ(options.stopsPerPlan, 5);
  EXPECT_EQ(options.mtspSeed, 7u);
  EXPECT_FALSE(options.broadcastVisited);
  EXPECT_FALSE(options.anchoredStarts);
  EXPECT_TRUE(KiosOptions::read(Config::fromText("", "run.ini")).anchoredStarts);
  config.requireAllKeysUsed();
  for (const auto& [text, key] : std::vector<std::pair<std::string, std::string>>{
           {"explore_standoff = 0", "explore_standoff"},
           {"explore_heights = 0", "explore_heights"},
           {"view_distance = 2", "view_distance"},
           {"waypoint_spacing = -1", "waypoint_spacing"},
           {"replan_period = nan", "replan_period"},
           {"max_waypoints = 0", "max_waypoints"},
           {"max_speed = 50", "max_speed"},
           {"map_resolution = 2", "map_resolution"},
           {"mtsp_starts = nearest", "mtsp_starts"},
           {"mtsp_seed = -3", "mtsp_seed"}}) {
    const auto bad = Config::fromText("[kios]\n" + text + "\n", "bad.ini");
    const auto message = testing::messageOf([&] { KiosOptions::read(bad); });
    EXPECT_MENTIONS(message, "bad.ini");
    EXPECT_MENTIONS(message, key);
  }
}

TEST(KiosStrategy, VisitedIdsSurviveTheMessageEncoding) {
  const std::vector<uint64_t> ids = {0, 1, 0x0123456789ABCDEFull, ~0ull};
  auto bytes = encodeIds(ids);
  EXPECT_EQ(bytes.size(), 32u);
  EXPECT_EQ(decodeIds(bytes), ids);
  bytes.pop_back();  // a truncated tail is dropped
  EXPECT_EQ(decodeIds(bytes), std::vector<uint64_t>(ids.begin(), ids.end() - 1));
}

TEST(KiosStrategy, IsRegisteredAndGroundStationsStayPut) {
  agent::StrategyRegistry registry;
  registerBuiltinStrategies(registry);
  ASSERT_TRUE(registry.has("kios"));
  const auto config = Config::fromText("", "run.ini");
  agent::StrategyContext context{config,
                                 "kios",
                                 "gcs",
                                 agent::Role::GroundStation,
                                 0,
                                 1,
                                 {{"gcs", agent::Role::GroundStation}},
                                 {},
                                 0.0};
  auto strategy = registry.create("kios", context);
  agent::AgentView view;
  view.role = agent::Role::GroundStation;
  const auto command = strategy->decide(view);
  EXPECT_FALSE(command.setpoint);
  EXPECT_FALSE(command.gimbal);
}

}  // namespace
}  // namespace coinspect::strategies::kios
