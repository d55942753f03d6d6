#include "coinspect/strategies/star/star_strategy.h"

#include <gtest/gtest.h>

#include <utility>

#include "coinspect/strategies/builtin.h"
#include "coinspect/testing/input_errors.h"

namespace coinspect::strategies::star {
namespace {

using agent::Role;

TEST(StarOptions, ReadsKeysStrictly) {
  const auto config = Config::fromText(
      "[star]\nmax_speed = 2\nview_distance = 0.7\nreplan_period = 3\nfrontier_margin = 5\n"
      "cluster_radius = 4\nyaw_weight = 0\nbroadcast_period = 1\nexplorers_inspect = false\n"
      "return_home = false\n",
      "run.ini");
  const auto options = StarOptions::read(config);
  EXPECT_DOUBLE_EQ(options.maxSpeed, 2.0);
  EXPECT_DOUBLE_EQ(options.viewDistance, 0.7);
  EXPECT_DOUBLE_EQ(options.replanPeriod, 3.0);
  EXPECT_DOUBLE_EQ(options.frontierMargin, 5.0);
  EXPECT_DOUBLE_EQ(options.clusterRadius, 4.0);
  EXPECT_DOUBLE_EQ(options.yawWeight, 0.0);
  EXPECT_DOUBLE_EQ(options.broadcastPeriod, 1.0);
  EXPECT_FALSE(options.explorersInspect);
  EXPECT_FALSE(options.returnHome);
  config.requireAllKeysUsed();

  for (const auto& [text, key] : std::vector<std::pair<std::string, std::string>>{
           {"max_speed = 0", "max_speed"},
           {"view_distance = 2", "view_distance"},
           {"replan_period = nan", "replan_period"},
           {"frontier_margin = x", "frontier_margin"},
           {"cluster_radius = -1", "cluster_radius"},
           {"yaw_weight = -0.5", "yaw_weight"},
           {"broadcast_period = 0", "broadcast_period"},
           {"explorers_inspect = maybe", "explorers_inspect"},
           {"return_home = 2", "return_home"}}) {
    const auto bad = Config::fromText("[star]\n" + text + "\n", "bad.ini");
    const auto message = testing::messageOf([&] { StarOptions::read(bad); });
    EXPECT_MENTIONS(message, "bad.ini");
    EXPECT_MENTIONS(message, key);
  }
}

agent::StrategyContext contextFor(const Config& config, const std::string& name, Role role,
                                  size_t index) {
  agent::CameraInfo camera;
  camera.horizontalFov = camera.verticalFov = 1.0;
  return agent::StrategyContext{config,
                                "star",
                                name,
                                role,
                                index,
                                1,
                                {{"gcs", Role::GroundStation},
                                 {"e1", Role::Explorer},
                                 {"p1", Role::Photographer},
                                 {"p2", Role::Photographer}},
                                camera,
                                role == Role::GroundStation ? 0.0 : 0.5};
}

TEST(StarStrategy, IsRegisteredAndGroundStationsStayPut) {
  agent::StrategyRegistry registry;
  registerBuiltinStrategies(registry);
  ASSERT_TRUE(registry.has("star"));
  const auto config = Config::fromText("", "run.ini");
  auto strategy = registry.create("star", contextFor(config, "gcs", Role::GroundStation, 0));
  agent::AgentView view;
  view.role = Role::GroundStation;
  const auto command = strategy->decide(view);
  EXPECT_FALSE(command.setpoint.has_value());
  EXPECT_TRUE(command.messages.empty());
}

TEST(StarStrategy, ReceivedInspectedPatchesAreKeptAndRelayed) {
  const auto config = Config::fromText("", "run.ini");
  StarStrategy photographer(contextFor(config, "p1", Role::Photographer, 2),
                            StarOptions::read(config));
  const std::vector<agent::BoxView> boxes{[] {
    agent::BoxView box;
    box.center = Vec3(30, 0, 10);
    box.size = Vec3(10, 10, 20);
    return box;
  }()};
  agent::AgentView view;
  view.name = "p1";
  view.role = Role::Photographer;
  view.index = 2;
  view.boxes = &boxes;
  view.odometry.position = Vec3(0, 0, 0.1);
  view.time = 1.0;
  view.messages.push_back({"p2", kInspectedTopic, encodeKeys({5, 3, 1000}), 1.0});
  view.messages.push_back({"p2", "other/topic", {0x80}, 1.0});  // not ours: ignored
  view.neighbours.push_back({"p2", Role::Photographer, {}});
  const auto command = photographer.decide(view);
  EXPECT_EQ(photographer.inspected(), (std::set<uint64_t>{3, 5, 1000}));
  EXPECT_TRUE(command.setpoint.has_value());
  // It passes what it learnt on to the units in sight.
  ASSERT_EQ(command.messages.size(), 1u);
  EXPECT_EQ(command.messages[0].topic, kInspectedTopic);
  std::vector<uint64_t> relayed;
  ASSERT_TRUE(decodeKeys(command.messages[0].bytes, &relayed));
  EXPECT_EQ(relayed, (std::vector<uint64_t>{3, 5, 1000}));
  // Not again within the broadcast period.
  view.messages.clear();
  view.time = 1.1;
  EXPECT_TRUE(photographer.decide(view).messages.empty());
}

}  // namespace
}  // namespace coinspect::strategies::star
