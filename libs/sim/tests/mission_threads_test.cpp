// Mission::setThreads: the decisions and sweeps of a tick on several threads give the run of one
// thread, bit for bit, including which messages a unit sees at the tick they were sent.
#include <gtest/gtest.h>

#include <optional>
#include <string>
#include <vector>

#include "coinspect/sim/mission.h"
#include "sim_scenes.h"

namespace coinspect::sim {
namespace {

// What one unit heard: when, from whom, sent when, what.
struct Heard {
  double time = 0.0;
  std::string from;
  double sent = 0.0;
  std::string text;
  bool operator==(const Heard& o) const {
    return time == o.time && from == o.from && sent == o.sent && text == o.text;
  }
};
using Transcript = std::vector<Heard>;

std::string text(const std::vector<uint8_t>& bytes) {
  return std::string(bytes.begin(), bytes.end());
}

// Answers what it heard: its broadcast carries how many messages it has received so far, so a
// message seen a tick earlier or later changes every later payload downstream. Unit `c` flies
// across the fleet (1 m above the others), so who is linked with whom changes during the run. Work
// of a length that depends on the unit makes the threads finish out of fleet order. Each unit
// writes only its own transcript (the strategies decide at once).
class Echo : public agent::Strategy {
 public:
  Echo(Transcript* transcript, size_t index) : transcript_(transcript), index_(index) {}

  agent::AgentCommand decide(const agent::AgentView& view) override {
    if (!start_) start_ = view.odometry.position;
    for (const auto& message : view.messages) {
      ++heard_;
      transcript_->push_back({view.time, message.from, message.time, text(message.bytes)});
    }
    volatile double sink = 0.0;
    for (size_t i = 0; i < 20000 * (5 - index_ % 5); ++i)
      sink = sink + 1e-9 * static_cast<double>(i);
    agent::AgentCommand command;
    if (view.role == agent::Role::GroundStation) return command;
    agent::AgentSetpoint setpoint;
    setpoint.position =
        view.name == "c" ? agent::Vec3(0.0, -4.0, 3.0) : agent::Vec3(start_->x(), start_->y(), 2.0);
    command.setpoint = setpoint;
    const std::string said = view.name + " heard " + std::to_string(heard_);
    command.messages.push_back({"", "echo", std::vector<uint8_t>(said.begin(), said.end())});
    return command;
  }

 private:
  Transcript* transcript_;
  size_t index_;
  std::optional<agent::Vec3> start_;
  size_t heard_ = 0;
};

struct Flown {
  std::vector<Transcript> transcripts;
  uint64_t digest = 0;
  uint64_t delivered = 0;
  size_t deaths = 0;
  size_t threads = 0;
};

Flown fly(size_t threads) {
  Flown run;
  run.transcripts.resize(5);  // gcs, a, b, c, d: never resized while they decide
  agent::StrategyRegistry registry;
  registry.registerStrategy("echo", [&run](const agent::StrategyContext& context) {
    return std::make_unique<Echo>(&run.transcripts.at(context.unitIndex), context.unitIndex);
  });
  const auto ini = Config::fromText(
      "[mission]\nexplorer_lidar = none\nlinks = range\nlink_range = 1.5\nbudget = 6\n"
      "[strategy]\nname = echo\n",
      "echo.ini");
  // Two pairs far apart (a-b and c-d linked), the station with neither; c then flies to a, b.
  Mission mission(testing::wallScenario({{"a", -4.0}, {"b", -3.0}, {"c", 3.0}, {"d", 4.0}}), ini,
                  registry);
  mission.setThreads(threads);
  run.threads = mission.threads();
  mission.run();
  run.digest = mission.stateDigest();
  run.delivered = mission.summary().messagesDelivered;
  run.deaths = mission.summary().deaths;
  return run;
}

TEST(MissionThreads, SeveralThreadsGiveTheRunOfOne) {
  const Flown one = fly(1);
  EXPECT_EQ(one.threads, 1u);
  EXPECT_GT(one.delivered, 30u);
  EXPECT_EQ(one.deaths, 0u);
  // In fleet order a unit sees at once what the units before it sent at the same tick, not what
  // those after it sent: b hears a at the tick a spoke, a hears b one decision later.
  const auto heardAtOnce = [](const Transcript& transcript, const std::string& from) {
    for (const auto& heard : transcript)
      if (heard.from == from && heard.sent == heard.time) return true;
    return false;
  };
  EXPECT_TRUE(heardAtOnce(one.transcripts[2], "a"));
  EXPECT_FALSE(heardAtOnce(one.transcripts[1], "b"));
  EXPECT_FALSE(one.transcripts[1].empty());
  for (const size_t threads : {2u, 3u, 4u}) {
    const Flown many = fly(threads);
    EXPECT_EQ(many.threads, threads);
    EXPECT_EQ(many.digest, one.digest) << threads << " threads";
    EXPECT_EQ(many.delivered, one.delivered) << threads << " threads";
    for (size_t unit = 0; unit < 5; ++unit)
      EXPECT_EQ(many.transcripts[unit], one.transcripts[unit])
          << threads << " threads, unit " << unit;
  }
}

}  // namespace
}  // namespace coinspect::sim
