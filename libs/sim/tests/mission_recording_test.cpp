// Recording a mission as a rawlog (doc/recording.md): what is written, in which order and how
// often, read back with RawlogReader; byte-identical for equal runs; errors stop the mission.
#include <gtest/gtest.h>
#include <mrpt/core/Clock.h>
#include <mrpt/obs/CObservationIMU.h>
#include <mrpt/obs/CObservationRobotPose.h>
#include <unistd.h>

#include <cinttypes>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "coinspect/core/version.h"
#include "coinspect/record/observations.h"
#include "coinspect/record/rawlog_reader.h"
#include "coinspect/sim/mission.h"
#include "coinspect/strategies/builtin.h"
#include "coinspect/testing/files.h"
#include "coinspect/testing/input_errors.h"
#include "coinspect/testing/paths.h"
#include "sim_scenes.h"

namespace coinspect::sim {
namespace {

using ObservationPtr = std::shared_ptr<mrpt::obs::CObservation>;
using coinspect::testing::messageOf;

agent::StrategyRegistry builtins() {
  agent::StrategyRegistry registry;
  strategies::registerBuiltinStrategies(registry);
  return registry;
}

// config/quick.ini (slei-b: a ground station, 2 explorers with LiDAR, 4 photographers) with a
// shorter budget and extra sections.
Config quickConfig(double budget, const std::string& extra = "") {
  const auto path = coinspect::testing::sourceDir() / "config" / "quick.ini";
  auto ini = Config::fromText(coinspect::testing::readFile(path) + "\n" + extra, path.string());
  ini.set("mission", "budget", std::to_string(budget));
  return ini;
}

record::RunHeader headerFor(const Mission& mission, const Config& ini) {
  char hash[17];
  std::snprintf(hash, sizeof hash, "%016" PRIx64, mission.scenario().contentHash());
  return {coinspect::version(), mission.config().seed, hash, ini.toText()};
}

struct Recorded {
  record::RunHeader header;
  std::vector<ObservationPtr> objects;  // after the header
  record::ReadStatus status;
};

Recorded readAll(const std::filesystem::path& path) {
  record::RawlogReader reader(path);
  Recorded out;
  out.header = reader.header();
  ObservationPtr observation;
  while (reader.next(observation))
    out.objects.push_back(observation);
  out.status = reader.status();
  return out;
}

std::map<std::string, size_t> labelCounts(const std::vector<ObservationPtr>& objects) {
  std::map<std::string, size_t> counts;
  for (const auto& o : objects)
    ++counts[o->sensorLabel];
  return counts;
}

double timeOf(const ObservationPtr& o) {
  return mrpt::Clock::toDouble(o->timestamp);
}

// MRPT timestamps have a resolution of 100 ns: simulated times come back to that precision.
constexpr double kTimeResolution = 1e-7;
bool isAt(const ObservationPtr& o, double time) {
  return std::abs(timeOf(o) - time) <= kTimeResolution;
}

template <class T>
std::vector<std::shared_ptr<T>> ofClass(const std::vector<ObservationPtr>& objects) {
  std::vector<std::shared_ptr<T>> out;
  for (const auto& o : objects)
    if (auto typed = std::dynamic_pointer_cast<T>(o)) out.push_back(typed);
  return out;
}

// Samples at t = 0, p, 2p, ... up to `end` (ticks are exact multiples of the step).
size_t samplesUpTo(double end, double period) {
  return static_cast<size_t>(std::floor(end / period + 1e-9)) + 1;
}

// Records `ini` into `path`; returns the finished mission's summary, events and GCS values.
struct RunResult {
  MissionSummary summary;
  std::vector<MissionEvent> events;
  std::vector<float> gcsValues;
  double gcsScore = 0.0;
  uint64_t digest = 0;
  std::optional<std::string> error;
};

RunResult fly(const Config& ini, const std::filesystem::path& rawlog,
              std::optional<uint64_t> seed = {}) {
  const auto registry = builtins();
  Mission mission(ini, registry, seed);
  ini.requireAllKeysUsed();
  if (!rawlog.empty()) mission.startRecording(rawlog, headerFor(mission, ini));
  mission.run();
  return {mission.summary(),  mission.events(),      mission.gcsValues(),
          mission.gcsScore(), mission.stateDigest(), mission.recordingError()};
}

// One short mission with a fault and a blackout, recorded once and checked in several tests.
class RecordedQuickMission : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    // ctest runs each test of the suite in its own process, possibly at once: one folder each.
    dir_ = new std::filesystem::path(
        coinspect::testing::scratchDir("sim-recording-quick-" + std::to_string(::getpid())));
    const auto& dir = *dir_;
    const auto ini = quickConfig(6.0,
                                 "[fault.1]\nunit = inspector4\nat = 3\n"
                                 "[blackout.1]\nfrom = 4\nto = 4.5\n");
    run_ = new RunResult(fly(ini, dir / "run.rawlog"));
    recorded_ = new Recorded(readAll(dir / "run.rawlog"));
    iniText_ = new std::string(ini.toText());
  }
  static void TearDownTestSuite() {
    delete run_;
    delete recorded_;
    delete iniText_;
    std::filesystem::remove_all(*dir_);
    delete dir_;
  }
  static std::filesystem::path* dir_;
  static RunResult* run_;
  static Recorded* recorded_;
  static std::string* iniText_;
};
std::filesystem::path* RecordedQuickMission::dir_ = nullptr;
RunResult* RecordedQuickMission::run_ = nullptr;
Recorded* RecordedQuickMission::recorded_ = nullptr;
std::string* RecordedQuickMission::iniText_ = nullptr;

TEST_F(RecordedQuickMission, ReadsBackCleanWithItsHeader) {
  EXPECT_FALSE(run_->error);
  EXPECT_TRUE(recorded_->status.clean) << recorded_->status.message;
  EXPECT_EQ(recorded_->status.objects, recorded_->objects.size() + 1);
  EXPECT_EQ(recorded_->header.coinspectVersion, coinspect::version());
  EXPECT_EQ(recorded_->header.seed, 1u);
  EXPECT_EQ(recorded_->header.scenarioHash.size(), 16u);
  EXPECT_EQ(recorded_->header.configIni, *iniText_);
  // The header's config reads back as the same mission config.
  const auto again = Config::fromText(recorded_->header.configIni, "header");
  EXPECT_EQ(MissionConfig::read(again).budget, 6.0);
  // Simulated time only goes forward through the file.
  for (size_t i = 1; i < recorded_->objects.size(); ++i)
    ASSERT_LE(timeOf(recorded_->objects[i - 1]), timeOf(recorded_->objects[i])) << i;
}

TEST_F(RecordedQuickMission, EveryLabelHasItsCount) {
  const auto counts = labelCounts(recorded_->objects);
  const auto& s = run_->summary;
  const size_t truth = samplesUpTo(s.simTime, 1.0 / 20.0);
  const size_t gimbal = samplesUpTo(s.simTime, 0.05);
  size_t lidar = 0;
  for (const auto& unit : s.units) {
    EXPECT_EQ(counts.count(unit.name + ".pose") ? counts.at(unit.name + ".pose") : 0, truth)
        << unit.name;
    EXPECT_EQ(counts.count(unit.name + ".imu") ? counts.at(unit.name + ".imu") : 0, truth)
        << unit.name;
    if (unit.role == "gcs") {
      EXPECT_EQ(counts.count(unit.name + ".camera"), 0u);
      EXPECT_EQ(counts.count(unit.name + ".gimbal"), 0u);
      continue;
    }
    EXPECT_EQ(counts.at(unit.name + ".camera"), unit.captures) << unit.name;
    EXPECT_EQ(counts.at(unit.name + ".gimbal"), gimbal) << unit.name;
    if (counts.count(unit.name + ".lidar")) lidar += counts.at(unit.name + ".lidar");
  }
  EXPECT_GT(lidar, 0u);
  EXPECT_EQ(lidar, s.keyFrames);  // key frames only by default
  EXPECT_GT(counts.at("gcs.links"), 0u);
  EXPECT_GT(counts.at("gcs.tally"), 0u);
  EXPECT_EQ(counts.count("gcs.messages"), 0u);  // demo-paths sends none
}

// Every MissionEvent is in the file, in order, with its numbered kind and the unit's label.
TEST_F(RecordedQuickMission, EventsMatchTheMissionsEventsInOrder) {
  const std::map<std::string, record::MissionEventKind> kinds = {
      {"mission-start", record::MissionEventKind::Start},
      {"mission-end", record::MissionEventKind::End},
      {"collision", record::MissionEventKind::Collision},
      {"fault", record::MissionEventKind::Failure},
      {"death", record::MissionEventKind::Death},
      {"no-takeoff", record::MissionEventKind::NoTakeoff},
      {"blackout-start", record::MissionEventKind::BlackoutStart},
      {"blackout-end", record::MissionEventKind::BlackoutEnd},
      {"activity-changed", record::MissionEventKind::ActivityChanged}};
  const auto events = ofClass<record::CObservationCoinspectEvent>(recorded_->objects);
  const auto& expected = run_->events;
  ASSERT_EQ(events.size(), expected.size());
  for (size_t i = 0; i < events.size(); ++i) {
    EXPECT_EQ(events[i]->kind, kinds.at(expected[i].kind)) << expected[i].kind;
    EXPECT_EQ(events[i]->unit, expected[i].unit);
    EXPECT_EQ(events[i]->detail, expected[i].detail);
    EXPECT_NEAR(timeOf(events[i]), expected[i].time, kTimeResolution);
    EXPECT_EQ(events[i]->sensorLabel,
              expected[i].unit.empty() ? "mission.event" : expected[i].unit + ".event");
  }
  // The death is there with its unit (eval tracks alive flags with it), and it comes before
  // the ground truth of its tick (faults are applied first).
  size_t death = recorded_->objects.size(), poseAtDeath = 0;
  for (size_t i = 0; i < recorded_->objects.size(); ++i) {
    const auto& o = recorded_->objects[i];
    const auto event = std::dynamic_pointer_cast<record::CObservationCoinspectEvent>(o);
    if (event && event->kind == record::MissionEventKind::Death) {
      EXPECT_EQ(event->unit, "inspector4");
      EXPECT_TRUE(isAt(o, 3.0)) << timeOf(o);
      death = i;
    }
    if (o->sensorLabel == "inspector4.pose" && isAt(o, 3.0)) poseAtDeath = i;
  }
  ASSERT_LT(death, recorded_->objects.size());
  EXPECT_LT(death, poseAtDeath);
}

// A capture's body state is the unit's ground-truth pose at the same instant, bit for bit.
TEST_F(RecordedQuickMission, CaptureBodyStateIsTheGroundTruthPose) {
  std::map<std::pair<std::string, int64_t>, mrpt::poses::CPose3D> poses;
  for (const auto& pose : ofClass<mrpt::obs::CObservationRobotPose>(recorded_->objects))
    poses[{pose->sensorLabel, pose->timestamp.time_since_epoch().count()}] = pose->pose.mean;
  size_t compared = 0;
  for (const auto& capture : ofClass<record::CObservationCoinspectCapture>(recorded_->objects)) {
    ASSERT_TRUE(capture->hasBodyState);
    const std::string unit = capture->sensorLabel.substr(0, capture->sensorLabel.find('.'));
    EXPECT_EQ(capture->occluders.size(), 5u);  // the other UAVs of slei-b
    const auto found = poses.find({unit + ".pose", capture->timestamp.time_since_epoch().count()});
    if (found == poses.end()) continue;
    ++compared;
    const auto& p = found->second;
    EXPECT_EQ(capture->bodyPosition[0], p.x());
    EXPECT_EQ(capture->bodyPosition[1], p.y());
    EXPECT_EQ(capture->bodyPosition[2], p.z());
    // The pose went through a rotation matrix: angles agree to rounding.
    EXPECT_NEAR(capture->bodyYaw, p.yaw(), 1e-9);
    EXPECT_NEAR(capture->bodyPitch, p.pitch(), 1e-9);
    EXPECT_NEAR(capture->bodyRoll, p.roll(), 1e-9);
  }
  EXPECT_GT(compared, 5u);
}

// Replaying the tally records gives the ground station's final values; link records show the
// blackout (every link down at 4 s, back at 4.5 s).
TEST_F(RecordedQuickMission, TallyAndLinkRecordsReplayTheGroundStation) {
  std::vector<float> values(run_->gcsValues.size(), 0.0f);
  const auto tallies = ofClass<record::CObservationCoinspectTally>(recorded_->objects);
  ASSERT_FALSE(tallies.empty());
  for (const auto& tally : tallies)
    for (const auto& change : tally->changes) {
      EXPECT_GT(static_cast<float>(change.value), values.at(change.index));
      values[change.index] = static_cast<float>(change.value);
    }
  EXPECT_EQ(values, run_->gcsValues);
  EXPECT_EQ(tallies.back()->totalScore, run_->gcsScore);
  EXPECT_EQ(tallies.back()->detected, run_->summary.detected);
  EXPECT_EQ(tallies.back()->pointCount, run_->summary.totalPoints);

  std::map<std::string, size_t> fleetIndex;
  for (const auto& unit : run_->summary.units)
    fleetIndex[unit.name] = fleetIndex.size();
  bool allDown = false, backUp = false;
  for (const auto& links : ofClass<record::CObservationCoinspectLinks>(recorded_->objects)) {
    ASSERT_FALSE(links->changes.empty());  // written only when something changed
    for (const auto& c : links->changes)   // lower fleet index first
      EXPECT_LT(fleetIndex.at(c.unitA), fleetIndex.at(c.unitB)) << c.unitA << " " << c.unitB;
    bool down = true, up = true;
    for (const auto& c : links->changes) {
      down = down && !c.linked;
      up = up && c.linked;
    }
    allDown = allDown || (isAt(links, 4.0) && down);
    backUp = backUp || (isAt(links, 4.5) && up);
  }
  EXPECT_TRUE(allDown);
  EXPECT_TRUE(backUp);
}

TEST(MissionRecording, RecordingDoesNotChangeTheMission) {
  const auto dir = coinspect::testing::scratchDir("sim-recording-unchanged");
  const auto recorded = fly(quickConfig(2.0), dir / "run.rawlog");
  const auto plain = fly(quickConfig(2.0), "");
  EXPECT_EQ(recorded.digest, plain.digest);
  EXPECT_EQ(recorded.gcsValues, plain.gcsValues);
  EXPECT_EQ(recorded.events.size(), plain.events.size());
}

TEST(MissionRecording, SameSeedSameBytesOtherSeedOtherBytes) {
  const auto dir = coinspect::testing::scratchDir("sim-recording-bytes");
  fly(quickConfig(2.0), dir / "a.rawlog", 5);
  fly(quickConfig(2.0), dir / "b.rawlog", 5);
  fly(quickConfig(2.0), dir / "c.rawlog", 6);
  const auto a = coinspect::testing::readFile(dir / "a.rawlog");
  EXPECT_GT(a.size(), 1000u);
  EXPECT_TRUE(a == coinspect::testing::readFile(dir / "b.rawlog"));
  EXPECT_FALSE(a == coinspect::testing::readFile(dir / "c.rawlog"));
}

TEST(MissionRecording, OptionsSetRatesAndLidar) {
  const auto dir = coinspect::testing::scratchDir("sim-recording-options");
  const auto run =
      fly(quickConfig(1.0, "[record]\nground_truth_rate = 100\nlidar = all\nflush_period = 0.25\n"),
          dir / "all.rawlog");
  const auto counts = labelCounts(readAll(dir / "all.rawlog").objects);
  EXPECT_EQ(counts.at("gcs.pose"), samplesUpTo(run.summary.simTime, 0.01));
  EXPECT_EQ(counts.at("explorer1.lidar"), samplesUpTo(run.summary.simTime, 0.1));  // 10 Hz
  fly(quickConfig(1.0, "[record]\nlidar = none\n"), dir / "none.rawlog");
  const auto none = labelCounts(readAll(dir / "none.rawlog").objects);
  EXPECT_EQ(none.count("explorer1.lidar"), 0u);
  EXPECT_EQ(none.count("explorer2.lidar"), 0u);
}

TEST(MissionRecording, BadRecordKeysAreNamed) {
  const auto registry = builtins();
  const auto error = [&](const std::string& extra) {
    return messageOf([&] { Mission(quickConfig(1.0, "[record]\n" + extra), registry); });
  };
  EXPECT_MENTIONS(error("ground_truth_rate = 0\n"), "[record] ground_truth_rate");
  EXPECT_MENTIONS(error("ground_truth_rate = 401\n"), "[record] ground_truth_rate");
  EXPECT_MENTIONS(error("flush_period = -1\n"), "[record] flush_period");
  EXPECT_MENTIONS(error("lidar = some\n"), "[record] lidar");
  EXPECT_MENTIONS(error("rawlog = perhaps\n"), "rawlog");
  // At most one ground-truth sample per physics step: 400 Hz at the default 2.5 ms is allowed.
  Mission(quickConfig(1.0, "[record]\nground_truth_rate = 400\n"), registry);
}

TEST(MissionRecording, UnwritablePathFailsBeforeTheMissionStarts) {
  const auto registry = builtins();
  const auto ini = quickConfig(1.0);
  Mission mission(ini, registry);
  const auto path =
      coinspect::testing::scratchDir("sim-recording-unwritable") / "no" / "run.rawlog";
  EXPECT_MENTIONS(messageOf([&] { mission.startRecording(path, headerFor(mission, ini)); }),
                  path.string());
  EXPECT_EQ(mission.time(), 0.0);
}

// A UAV that sends a message to the ground station, a broadcast and a message to a unit that
// does not exist at every decision.
class Chatty : public agent::Strategy {
 public:
  agent::AgentCommand decide(const agent::AgentView& view) override {
    agent::AgentCommand command;
    if (view.role == agent::Role::GroundStation) return command;
    command.messages.push_back({"gcs", "report", std::vector<uint8_t>(10)});
    command.messages.push_back({"", "hello", std::vector<uint8_t>(3)});
    command.messages.push_back({"nobody", "lost", std::vector<uint8_t>(1)});
    return command;
  }
};

// gcs.messages holds every message the network decided about, with its size and fate, one
// record per tick: they add up to the summary's counters.
TEST(MissionRecording, MessagesWithSizesAndFate) {
  agent::StrategyRegistry registry;
  registry.registerStrategy(
      "chatty", [](const agent::StrategyContext&) { return std::make_unique<Chatty>(); });
  const auto ini = Config::fromText(
      "[mission]\nexplorer_lidar = none\nbudget = 1\nstart_timeout = 1\n"
      "[strategy]\nname = chatty\n[blackout.1]\nfrom = 0.5\nto = 0.7\nunits = a\n",
      "chatty.ini");
  Mission mission(testing::wallScenario({{"a", -1.0}, {"b", 1.0}}), ini, registry);
  const auto dir = coinspect::testing::scratchDir("sim-recording-messages");
  mission.startRecording(dir / "run.rawlog", headerFor(mission, ini));
  mission.run();
  ASSERT_FALSE(mission.recordingError());
  const auto recorded = readAll(dir / "run.rawlog");
  EXPECT_TRUE(recorded.status.clean) << recorded.status.message;
  uint64_t sent = 0, delivered = 0, dropped = 0;
  for (const auto& log : ofClass<record::CObservationCoinspectMessages>(recorded.objects)) {
    EXPECT_EQ(log->sensorLabel, "gcs.messages");
    for (const auto& m : log->messages) {
      ++sent;
      (m.delivered ? delivered : dropped) += 1;
      // Payload + 32 header bytes.
      EXPECT_EQ(m.bytes, m.topic == "report" ? 42u : m.topic == "hello" ? 35u : 33u);
      EXPECT_TRUE(m.from == "a" || m.from == "b");
      if (m.topic == "lost") {
        EXPECT_EQ(m.to, "nobody");
        EXPECT_FALSE(m.delivered);
      }
    }
  }
  const auto summary = mission.summary();
  EXPECT_GT(sent, 0u);
  EXPECT_GT(dropped, 0u);  // during a's blackout
  EXPECT_EQ(sent, summary.messagesSent);
  EXPECT_EQ(delivered, summary.messagesDelivered);
  EXPECT_EQ(dropped, summary.messagesDropped);
}

}  // namespace
}  // namespace coinspect::sim
