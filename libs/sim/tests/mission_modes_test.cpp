// Run modes: lockstep applies a command at once, latency delays it by the decision's measured
// compute time, realtime paces the loop to the wall clock.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstring>
#include <memory>
#include <thread>
#include <vector>

#include "coinspect/sim/mission.h"
#include "coinspect/testing/files.h"
#include "coinspect/testing/input_errors.h"
#include "coinspect/testing/paths.h"
#include "coinspect/world/scenario_files.h"
#include "sim_scenes.h"

namespace coinspect::sim {
namespace {

using testing::wallScenario;
using WallClock = std::chrono::steady_clock;

// What the slow strategy and the listening ground station saw.
struct Trace {
  std::vector<double> computeTimes;  // s of wall time each decision of the UAV took (>= sleep)
  struct Delivery {
    double decidedAt = 0.0;  // simulated s, carried in the payload
    double sentAt = 0.0;     // simulated s, stamped when the command was applied
  };
  std::vector<Delivery> deliveries;
};

// Sleeps `sleep` of wall time, then commands a climb to 3 m and sends its decision time to the
// ground station: the message's send time tells when the command was applied.
class SlowClimb : public agent::Strategy {
 public:
  SlowClimb(Trace& trace, std::chrono::milliseconds sleep) : trace_(trace), sleep_(sleep) {}
  agent::AgentCommand decide(const agent::AgentView& view) override {
    const auto start = WallClock::now();
    std::this_thread::sleep_for(sleep_);
    agent::AgentCommand command;
    agent::AgentSetpoint setpoint;
    setpoint.position = agent::Vec3(view.odometry.position.x(), view.odometry.position.y(), 3.0);
    command.setpoint = setpoint;
    agent::OutgoingMessage message{"gcs", "decided", std::vector<uint8_t>(sizeof(double))};
    std::memcpy(message.bytes.data(), &view.time, sizeof(double));
    command.messages.push_back(message);
    trace_.computeTimes.push_back(std::chrono::duration<double>(WallClock::now() - start).count());
    return command;
  }

 private:
  Trace& trace_;
  std::chrono::milliseconds sleep_;
};

// The ground station stays put and logs what it receives.
class Listener : public agent::Strategy {
 public:
  explicit Listener(Trace& trace) : trace_(trace) {}
  agent::AgentCommand decide(const agent::AgentView& view) override {
    for (const auto& message : view.messages) {
      double decidedAt = 0.0;
      std::memcpy(&decidedAt, message.bytes.data(), sizeof(double));
      trace_.deliveries.push_back({decidedAt, message.time});
    }
    return {};
  }
  double decisionRate() const override { return 40.0; }

 private:
  Trace& trace_;
};

agent::StrategyRegistry slowRegistry(Trace& trace, std::chrono::milliseconds sleep) {
  agent::StrategyRegistry registry;
  registry.registerStrategy("slow", [&trace, sleep](const agent::StrategyContext& context) {
    return context.role == agent::Role::GroundStation
               ? std::unique_ptr<agent::Strategy>(std::make_unique<Listener>(trace))
               : std::make_unique<SlowClimb>(trace, sleep);
  });
  return registry;
}

Config modeConfig(const std::string& mode, const std::string& extra = "") {
  return Config::fromText("[mission]\nexplorer_lidar = none\nbudget = 1\nrun_mode = " + mode +
                              "\n" + extra + "[strategy]\nname = slow\n",
                          mode + ".ini");
}

// Simulated time at which the UAV first leaves the ground (it idles there until commanded).
double takeOffTime(Mission& mission) {
  const size_t a = mission.unitIndex("a");
  while (mission.unitState(a).position.z() < 1e-3 && mission.time() < 1.0)
    mission.step();
  return mission.time();
}

TEST(MissionModes, LockstepAppliesACommandAtTheTickItWasDecided) {
  Trace trace;
  const auto registry = slowRegistry(trace, std::chrono::milliseconds(20));
  const auto config = modeConfig("lockstep");
  Mission mission(wallScenario({{"a", 0.0}}), config, registry);
  config.requireAllKeysUsed();
  mission.runUntil(0.35);
  ASSERT_GE(trace.deliveries.size(), 3u);
  for (const auto& delivery : trace.deliveries)
    EXPECT_EQ(delivery.sentAt, delivery.decidedAt);
  EXPECT_EQ(mission.summary().runMode, "lockstep");
}

TEST(MissionModes, LatencyDelaysEachCommandByItsComputeTime) {
  Trace trace;
  const auto registry = slowRegistry(trace, std::chrono::milliseconds(20));
  const auto config = modeConfig("latency");
  Mission mission(wallScenario({{"a", 0.0}}), config, registry);
  mission.runUntil(0.35);
  // Decisions at 0, 0.1, 0.2, 0.3 s; each message left when its command was applied.
  ASSERT_GE(trace.deliveries.size(), 3u);
  ASSERT_LE(trace.deliveries.size(), trace.computeTimes.size());
  for (size_t i = 0; i < trace.deliveries.size(); ++i) {
    const auto& delivery = trace.deliveries[i];
    EXPECT_GE(delivery.sentAt - delivery.decidedAt, trace.computeTimes[i] - 1e-9)
        << "decision " << i;
    // Applied on a tick: a whole number of physics steps.
    EXPECT_NEAR(std::remainder(delivery.sentAt, 0.0025), 0.0, 1e-9);
    if (i > 0) {
      EXPECT_GE(delivery.sentAt, trace.deliveries[i - 1].sentAt);  // decision order
    }
  }
  const auto summary = mission.summary();
  EXPECT_EQ(summary.runMode, "latency");
  EXPECT_GE(summary.decisionTimes.count, trace.computeTimes.size());
  EXPECT_GE(summary.decisionTimes.max, 0.020);
  EXPECT_NE(formatSummary(summary).find("not deterministic"), std::string::npos);
}

TEST(MissionModes, LatencyDelaysTheTakeOff) {
  // Only the first decision (t = 0) matters: the UAV idles on the ground until its climb command
  // applies, at the first tick at or after 20 ms in latency mode.
  Trace lockTrace, latencyTrace;
  const auto lockRegistry = slowRegistry(lockTrace, std::chrono::milliseconds(20));
  const auto latencyRegistry = slowRegistry(latencyTrace, std::chrono::milliseconds(20));
  const auto lockConfig = modeConfig("lockstep");
  const auto latencyConfig = modeConfig("latency");
  Mission lockstep(wallScenario({{"a", 0.0}}), lockConfig, lockRegistry);
  Mission latency(wallScenario({{"a", 0.0}}), latencyConfig, latencyRegistry);
  const double lockTakeOff = takeOffTime(lockstep);
  const double latencyTakeOff = takeOffTime(latency);
  ASSERT_LT(latencyTakeOff, 1.0);
  ASSERT_FALSE(latencyTrace.computeTimes.empty());
  EXPECT_GE(latencyTakeOff, lockTakeOff + latencyTrace.computeTimes.front() - 1e-9);
}

// The loop sleeps at controller ticks so that simulated time never runs ahead of the wall clock
// (lower bounds only: a slow machine may take longer, never shorter).
double wallSecondsForOneSimulatedSecond(const std::string& extra) {
  Trace trace;
  const auto registry = slowRegistry(trace, std::chrono::milliseconds(0));
  const auto config = modeConfig("realtime", extra);
  Mission mission(wallScenario({{"a", 0.0}}), config, registry);
  const auto start = WallClock::now();
  mission.runUntil(1.0);
  EXPECT_EQ(mission.summary().runMode, "realtime");
  return std::chrono::duration<double>(WallClock::now() - start).count();
}

TEST(MissionModes, RealtimeIsPacedToTheWallClock) {
  EXPECT_GE(wallSecondsForOneSimulatedSecond(""), 0.9);
  EXPECT_GE(wallSecondsForOneSimulatedSecond("realtime_factor = 2\n"), 0.45);
}

std::string readError(const std::string& mission) {
  const auto config =
      Config::fromText("[mission]\n" + mission + "[strategy]\nname = slow\n", "modes.ini");
  return coinspect::testing::messageOf([&] { MissionConfig::read(config); });
}

TEST(MissionModes, BadRunModeValuesNameTheKey) {
  EXPECT_MENTIONS(readError("run_mode = fast\n"), "[mission] run_mode");
  EXPECT_MENTIONS(readError("run_mode = realtime\nrealtime_factor = 0\n"),
                  "[mission] realtime_factor");
  EXPECT_MENTIONS(readError("run_mode = realtime\nrealtime_factor = -1\n"),
                  "[mission] realtime_factor");
  EXPECT_MENTIONS(readError("run_mode = realtime\nrealtime_factor = nan\n"),
                  "[mission] realtime_factor");
  // A factor that would be ignored is refused too.
  EXPECT_MENTIONS(readError("realtime_factor = 2\n"), "[mission] realtime_factor");
  const auto fine = Config::fromText(
      "[mission]\nrun_mode = realtime\nrealtime_factor = 2.5\n[strategy]\nname = x\n", "ok.ini");
  const auto read = MissionConfig::read(fine);
  EXPECT_EQ(read.runMode, RunMode::Realtime);
  EXPECT_EQ(read.realtimeFactor, 2.5);
  EXPECT_EQ(MissionConfig::read(Config::fromText("[strategy]\nname = x\n", "d.ini")).runMode,
            RunMode::Lockstep);
}

// `[mission] fleet`: three counts for a generated slei-* scene, nothing else.
TEST(MissionConfigFleet, ResizesAGeneratedSleiFleetAndNamesTheKeyOtherwise) {
  const auto read = [](const std::string& mission) {
    return MissionConfig::read(
        Config::fromText("[mission]\n" + mission + "[strategy]\nname = x\n", "fleet.ini"));
  };
  const auto config = read("scenario = slei-b\nfleet = 2 1 3\n");
  ASSERT_TRUE(config.fleet);
  const auto scenario = loadMissionScenario(config);
  size_t stations = 0;
  for (const auto& unit : scenario.fleet)
    stations += unit.role == world::UnitRole::GroundStation;
  EXPECT_EQ(stations, 2u);
  EXPECT_EQ(scenario.fleet.size(), 6u);
  EXPECT_FALSE(read("scenario = slei-b\n").fleet);
  for (const char* bad : {"fleet = 1 2\n", "fleet = 1 2 4 5\n", "fleet = 0 2 4\n",
                          "fleet = 1 x 4\n", "fleet = 1 2 -4\n", "fleet = 1 2 4.5\n"})
    EXPECT_MENTIONS(readError(bad), "[mission] fleet");
  EXPECT_MENTIONS(coinspect::testing::messageOf(
                      [&] { loadMissionScenario(read("scenario = hangar\nfleet = 1 2 4\n")); }),
                  "[mission] fleet");
}

// `[mission] scenario`: a generator's name is the generator even when the INI's folder holds a
// folder of that name (a run's output, `--out slei-b`); any other value is a path from the INI's
// folder.
TEST(MissionConfigScenario, AGeneratorNameIsNotHiddenByAFolderBesideTheIni) {
  const auto dir = coinspect::testing::scratchDir("mission_scenario_source");
  std::filesystem::create_directories(dir / "slei-b");
  world::saveScenario(world::generateScenario("slei-b", 3), dir / "scene");
  const auto read = [&](const std::string& scenario) {
    coinspect::testing::writeFile(dir / "mission.ini", "[mission]\nscenario = " + scenario +
                                                           "\nscenario_seed = 3\n"
                                                           "[strategy]\nname = x\n");
    return MissionConfig::read(Config::fromFile(dir / "mission.ini"));
  };
  const auto generatedHash = world::generateScenario("slei-b", 3).contentHash();
  const auto named = read("slei-b");
  EXPECT_EQ(named.scenario, "slei-b");
  EXPECT_EQ(loadMissionScenario(named).contentHash(), generatedHash);
  const auto folder = read("scene");
  EXPECT_EQ(folder.scenario, (dir / "scene").string());
  EXPECT_EQ(loadMissionScenario(folder).contentHash(), generatedHash);
  const std::string missing =
      coinspect::testing::messageOf([&] { loadMissionScenario(read("nowhere")); });
  EXPECT_MENTIONS(missing, "mission.ini");
  EXPECT_MENTIONS(missing, "[mission] scenario");
  EXPECT_MENTIONS(missing, (dir / "nowhere").string());
}

}  // namespace
}  // namespace coinspect::sim
