#include "coinspect/strategies/coinspect/coinspect_strategy.h"

#include <gtest/gtest.h>

#include <utility>

#include "coinspect/strategies/builtin.h"
#include "coinspect/testing/input_errors.h"

namespace coinspect::strategies::coinspect_strategy {
namespace {

TEST(CoinspectOptions, ReadsKeysStrictly) {
  const auto config = Config::fromText(
      "[coinspect]\nexplore_time = 0\nview_distance = 0.8\ndeliver_period = 90\n", "run.ini");
  const auto options = CoinspectOptions::read(config);
  EXPECT_DOUBLE_EQ(options.exploreTime, 0.0);
  EXPECT_DOUBLE_EQ(options.viewDistance, 0.8);
  EXPECT_DOUBLE_EQ(options.delivery.period, 90.0);
  config.requireAllKeysUsed();
  for (const auto& [text, key] : std::vector<std::pair<std::string, std::string>>{
           {"explore_time = -1", "explore_time"},
           {"view_distance = 2.5", "view_distance"},
           {"transit_speed = nan", "transit_speed"},
           {"explorer_capacity = 0", "explorer_capacity"}}) {
    const auto bad = Config::fromText("[coinspect]\n" + text + "\n", "bad.ini");
    const auto message = testing::messageOf([&] { CoinspectOptions::read(bad); });
    EXPECT_MENTIONS(message, "bad.ini");
    EXPECT_MENTIONS(message, key);
  }
}

TEST(CoinspectStrategy, IsRegisteredAndGroundStationsStayPut) {
  agent::StrategyRegistry registry;
  registerBuiltinStrategies(registry);
  ASSERT_TRUE(registry.has("coinspect"));
  const auto config = Config::fromText("", "run.ini");
  agent::StrategyContext context{config,
                                 "coinspect",
                                 "gcs",
                                 agent::Role::GroundStation,
                                 0,
                                 1,
                                 {{"gcs", agent::Role::GroundStation}},
                                 {},
                                 0.0};
  auto strategy = registry.create("coinspect", context);
  agent::AgentView view;
  view.role = agent::Role::GroundStation;
  const auto command = strategy->decide(view);
  EXPECT_FALSE(command.setpoint);
  EXPECT_FALSE(command.gimbal);
}

}  // namespace
}  // namespace coinspect::strategies::coinspect_strategy
