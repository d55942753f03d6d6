#include <gtest/gtest.h>

#include "coinspect/agent/strategy.h"
#include "coinspect/core/config.h"
#include "coinspect/testing/input_errors.h"

namespace coinspect::agent {
namespace {

// Hovers where it is, at a rate read from its own config key.
class HoverHere : public Strategy {
 public:
  explicit HoverHere(double rate) : rate_(rate) {}
  AgentCommand decide(const AgentView& view) override {
    AgentCommand command;
    command.setpoint =
        AgentSetpoint{view.odometry.position, Vec3::Zero(), Vec3::Zero(), view.odometry.yaw};
    return command;
  }
  double decisionRate() const override { return rate_; }

 private:
  double rate_;
};

StrategyRegistry registryWithHover() {
  StrategyRegistry registry;
  registry.registerStrategy("hover", [](const StrategyContext& context) {
    return std::make_unique<HoverHere>(context.config.getDouble("hover", "rate", 10.0));
  });
  return registry;
}

TEST(StrategyRegistry, CreatesByNameAndPassesTheConfig) {
  const auto registry = registryWithHover();
  const auto config = Config::fromText("[hover]\nrate = 25\n", "test.ini");
  const StrategyContext context{config, "hover", "jurong", Role::Explorer, 1, 7, {}, {}, 0.0};
  auto strategy = registry.create("hover", context);
  EXPECT_DOUBLE_EQ(strategy->decisionRate(), 25.0);
  AgentView view;
  view.odometry.position = Vec3(1, 2, 3);
  const auto command = strategy->decide(view);
  ASSERT_TRUE(command.setpoint.has_value());
  EXPECT_EQ(command.setpoint->position, Vec3(1, 2, 3));
  EXPECT_FALSE(command.gimbal.has_value());
  EXPECT_NO_THROW(config.requireAllKeysUsed());
}

TEST(StrategyRegistry, UnknownNameListsTheKnownOnes) {
  const auto registry = registryWithHover();
  const auto config = Config::fromText("", "run.ini");
  const StrategyContext context{config, "nope", "jurong", Role::Explorer, 0, 0, {}, {}, 0.0};
  const auto message = testing::messageOf([&] { registry.create("nope", context); });
  EXPECT_MENTIONS(message, "nope");
  EXPECT_MENTIONS(message, "hover");
  EXPECT_MENTIONS(message, "run.ini");
}

TEST(StrategyRegistry, RejectsDuplicatesAndEmptyNames) {
  auto registry = registryWithHover();
  const auto factory = [](const StrategyContext&) { return std::make_unique<HoverHere>(1.0); };
  EXPECT_THROW(registry.registerStrategy("hover", factory), InputError);
  EXPECT_THROW(registry.registerStrategy("", factory), InputError);
  EXPECT_TRUE(registry.has("hover"));
  EXPECT_EQ(registry.names(), std::vector<std::string>{"hover"});
}

}  // namespace
}  // namespace coinspect::agent
