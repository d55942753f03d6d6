// Feature missions (objective = features): detection, inspection, store and forward, collection,
// meetings and reported activities, with a scripted strategy on a wall with three features.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>

#include "coinspect/sim/mission.h"
#include "coinspect/testing/input_errors.h"
#include "sim_scenes.h"

namespace coinspect::sim {
namespace {

// The wall of sim_scenes.h (face x = 10) with three features at 4 m height, y = -1, 0, 1; the
// station at (0, 0, 1), explorer "e" at (0, -3), inspector "i" at (0, 3).
world::Scenario featureScene() {
  world::Scenario scenario;
  scenario.name = "feature-wall";
  scenario.meshes.push_back(testing::boxMesh({10, -5, 0}, {11, 5, 10}));
  std::vector<world::InterestPoint> points;
  for (int y = -1; y <= 1; ++y) {
    world::InterestPoint p;
    p.position = world::Vec3(10.0, y, 4.0);
    p.normal = world::Vec3(-1, 0, 0);
    points.push_back(p);
  }
  scenario.interestPoints = world::InterestPointSet(points);
  world::OrientedBox box;
  box.name = "face";
  box.center = world::Vec3(10, 0, 4);
  box.size = world::Vec3(1, 4, 2);
  scenario.boxes.push_back(box);
  scenario.fleet = {testing::unitAt("gcs", world::UnitRole::GroundStation, {0, 0, 1}),
                    testing::unitAt("e", world::UnitRole::Explorer, {0, -3, 0}),
                    testing::unitAt("i", world::UnitRole::Photographer, {0, 3, 0})};
  scenario.missionBudget = 40.0;
  return scenario;
}

// What every unit saw of features, by unit name.
struct Seen {
  std::map<std::string, std::vector<agent::FeatureView>> detected;
  std::map<std::string, std::vector<uint32_t>> inspected, received;
  std::vector<bool> urgentBoxes;     // the boxes' highPriority flags as the units see them
  std::vector<double> detectRanges;  // the fleet's, as the strategies are told
};

// The explorer hovers at (6.5, -2, 4) facing the wall; the inspector hovers 5 m from it, camera
// level, until `leaveAt`, then turns away and flies back next to the station. The station does not
// move.
class Scripted final : public agent::Strategy {
 public:
  Scripted(std::string name, double leaveAt, Seen& seen)
      : name_(std::move(name)), leaveAt_(leaveAt), seen_(seen) {}
  agent::AgentCommand decide(const agent::AgentView& view) override {
    auto& detected = seen_.detected[name_];
    detected.insert(detected.end(), view.detectedFeatures.begin(), view.detectedFeatures.end());
    auto& inspected = seen_.inspected[name_];
    inspected.insert(inspected.end(), view.inspectedFeatures.begin(), view.inspectedFeatures.end());
    auto& received = seen_.received[name_];
    received.insert(received.end(), view.receivedResults.begin(), view.receivedResults.end());
    if (view.boxes && seen_.urgentBoxes.empty())
      for (const auto& box : *view.boxes)
        seen_.urgentBoxes.push_back(box.highPriority);
    agent::AgentCommand command;
    if (name_.rfind("gcs", 0) == 0) return command;  // the stations stay where they are
    agent::AgentSetpoint setpoint;
    command.gimbal = agent::GimbalCommand::angles(0.0, 0.0);
    if (name_ == "e") {
      setpoint.position = agent::Vec3(6.5, -2, 4);
      command.activity = agent::Activity::Exploring;
      command.assignedFeatures = view.detectedFeatures.empty()
                                     ? std::vector<uint32_t>{}
                                     : std::vector<uint32_t>{view.detectedFeatures[0].id};
    } else if (view.time < leaveAt_) {
      setpoint.position = agent::Vec3(5, 0, 4);
      command.activity = agent::Activity::Inspecting;
    } else {
      setpoint.position = agent::Vec3(1.5, 0, 2);
      setpoint.yaw = M_PI;  // turned away from the wall
      command.activity = agent::Activity::TravellingToMeeting;
    }
    command.setpoint = setpoint;
    return command;
  }

 private:
  std::string name_;
  double leaveAt_;
  Seen& seen_;
};

agent::StrategyRegistry scripted(double leaveAt, Seen& seen) {
  agent::StrategyRegistry registry;
  registry.registerStrategy("scripted", [leaveAt, &seen](const agent::StrategyContext& context) {
    seen.detectRanges.clear();
    for (const auto& member : context.fleet)
      seen.detectRanges.push_back(member.detectRange);
    return std::make_unique<Scripted>(context.unitName, leaveAt, seen);
  });
  return registry;
}

const std::string kFeatureMission =
    "[mission]\nexplorer_lidar = none\nlinks = range\nlink_range = 5\nobjective = features\n"
    "[strategy]\nname = scripted\n";

bool hasEvent(const Mission& mission, const std::string& kind, const std::string& detail) {
  const auto& events = mission.events();
  return std::any_of(events.begin(), events.end(),
                     [&](const MissionEvent& e) { return e.kind == kind && e.detail == detail; });
}

TEST(FeatureMission, DetectedInspectedCarriedAndCollectedThenTheMissionEnds) {
  Seen seen;
  const auto registry = scripted(12.0, seen);
  const auto config = Config::fromText(kFeatureMission, "features.ini");
  Mission mission(featureScene(), config, registry);
  config.requireAllKeysUsed();
  mission.run();
  const auto summary = mission.summary();
  const auto& f = summary.features;
  ASSERT_TRUE(f.enabled);
  EXPECT_EQ(f.total, 3u);
  EXPECT_EQ(f.discovered, 3u);
  EXPECT_EQ(f.inspected, 3u);
  EXPECT_EQ(f.collected, 3u);
  EXPECT_DOUBLE_EQ(f.finishRate(), 1.0);
  EXPECT_EQ(f.assigned, 3u);
  // The results reach the station only once the inspector is back in range (after 12 s), and
  // the mission stops there, well before its 40 s budget.
  ASSERT_TRUE(f.finishTime);
  EXPECT_GT(*f.finishTime, 12.0);
  EXPECT_LT(*f.finishTime, 20.0);
  EXPECT_NEAR(summary.missionTime, *f.finishTime, 0.05);
  EXPECT_TRUE(hasEvent(mission, "mission-end", "all features collected"));
  for (size_t k = 0; k < 3; ++k) {
    // An inspection takes 3 s of keeping the feature in view: not before the 3rd second.
    EXPECT_GE(f.inspectedAt[k], 3.0);
    EXPECT_LT(f.inspectedAt[k], 12.0);
    EXPECT_GE(f.collectedAt[k], 12.0);
    EXPECT_LE(f.discoveredAt[k], f.inspectedAt[k]);
    EXPECT_TRUE(hasEvent(mission, "feature-collected", "feature " + std::to_string(k)));
  }
  // What the robots were told: the explorer its detections (with the features' true poses), the
  // inspector its inspections. (The mission ended before the station's next decision.)
  ASSERT_EQ(seen.detected["e"].size(), 3u);
  for (const auto& d : seen.detected["e"]) {
    EXPECT_NEAR(d.position.x(), 10.0, 1e-6);
    EXPECT_NEAR(d.normal.x(), -1.0, 1e-6);
  }
  EXPECT_TRUE(seen.detected["i"].empty());  // inspectors have no detector
  auto inspected = seen.inspected["i"];
  std::sort(inspected.begin(), inspected.end());
  EXPECT_EQ(inspected, (std::vector<uint32_t>{0, 1, 2}));
  EXPECT_EQ(f.units[mission.unitIndex("gcs")].held, 3u);
  // The explorer met the inspector out at the wall and carries the results too.
  EXPECT_EQ(seen.received["e"].size(), 3u);
  EXPECT_EQ(f.meetingsExplorerInspector, 1u);
  EXPECT_EQ(f.meetingsGcsExplorer, 0u);
  EXPECT_EQ(f.meetingsOther, 1u);  // the inspector back at the station
  const size_t i = mission.unitIndex("i");
  EXPECT_EQ(f.units[i].inspected, 3u);
  EXPECT_EQ(f.units[mission.unitIndex("e")].detected, 3u);
  EXPECT_EQ(f.units[mission.unitIndex("e")].held, 3u);
  // The inspector said "inspecting" until 12 s of simulated time, then "travelling".
  const auto& seconds = f.units[i].activitySeconds;
  EXPECT_NEAR(seconds[static_cast<size_t>(agent::Activity::Inspecting)], 12.0 - summary.startTime,
              0.15);
  EXPECT_NEAR(seconds[static_cast<size_t>(agent::Activity::TravellingToMeeting)],
              *f.finishTime - (12.0 - summary.startTime), 0.15);
}

// The timeline of activities (coinspect plot-timeline): every unit's activity when the mission
// clock starts (the station never reports one), then each change, as "activity-changed" events.
TEST(FeatureMission, ActivityChangesAreEventsFromTheStartOfTheMissionClock) {
  Seen seen;
  const auto registry = scripted(12.0, seen);
  Mission mission(featureScene(), Config::fromText(kFeatureMission, "features.ini"), registry);
  mission.run();
  const double start = mission.summary().startTime;
  std::vector<MissionEvent> activities;
  bool startSeen = false;
  for (const auto& e : mission.events()) {
    startSeen = startSeen || e.kind == "mission-start";
    if (e.kind != "activity-changed") continue;
    EXPECT_TRUE(startSeen) << "an activity event before the mission-start event";
    activities.push_back(e);
  }
  ASSERT_EQ(activities.size(), 4u);
  const std::vector<std::pair<std::string, std::string>> expected = {
      {"gcs", "unreported"},
      {"e", "exploring"},
      {"i", "inspecting"},
      {"i", "travelling-to-meeting"}};
  for (size_t k = 0; k < expected.size(); ++k) {
    EXPECT_EQ(activities[k].unit, expected[k].first) << k;
    EXPECT_EQ(activities[k].detail, expected[k].second) << k;
  }
  for (size_t k = 0; k < 3; ++k)
    EXPECT_DOUBLE_EQ(activities[k].time, start);
  // The inspector's first decision at or after 12 s of simulated time.
  EXPECT_GE(activities[3].time, 12.0);
  EXPECT_LT(activities[3].time, 12.5);
}

TEST(FeatureMission, WithoutAMeetingNothingIsCollectedAndTheBudgetEndsIt) {
  Seen seen;
  const auto registry = scripted(1e9, seen);  // the inspector never comes back
  const auto config = Config::fromText(kFeatureMission, "features.ini");
  Mission mission(featureScene(), config, registry);
  mission.run();
  const auto f = mission.summary().features;
  EXPECT_EQ(f.inspected, 3u);
  EXPECT_EQ(f.collected, 0u);
  EXPECT_DOUBLE_EQ(f.finishRate(), 0.0);
  EXPECT_FALSE(f.finishTime);
  EXPECT_TRUE(hasEvent(mission, "mission-end", "budget used"));
  EXPECT_EQ(f.units[mission.unitIndex("i")].held, 3u);
  EXPECT_TRUE(std::isnan(f.collectedAt[0]));
}

// A scenario file's fleet without a station or an explorer flew a feature mission that could
// never collect anything, and exited 0 (fuzzing): it is refused, naming the key and the counts.
TEST(FeatureMission, AFleetWithoutAStationOrAnExplorerIsRefused) {
  Seen seen;
  const auto registry = scripted(12.0, seen);
  const auto config = Config::fromText(kFeatureMission, "features.ini");
  auto noStation = featureScene();
  noStation.fleet[0].role = world::UnitRole::Explorer;
  std::string message =
      coinspect::testing::messageOf([&] { Mission(noStation, config, registry); });
  EXPECT_MENTIONS(message, "features.ini: [mission] objective");
  EXPECT_MENTIONS(message, "'feature-wall' has 0 stations and 2 explorers");
  auto noExplorer = featureScene();
  noExplorer.fleet[1].role = world::UnitRole::Photographer;
  message = coinspect::testing::messageOf([&] { Mission(noExplorer, config, registry); });
  EXPECT_MENTIONS(message, "has 1 stations and 0 explorers");
}

// Several stations (the paper's several GCS): a result counts when any station receives it.
// Here the first station stands 20 m off, out of everyone's reach; a second one beside the
// inspector's way back collects everything, and the mission ends.
TEST(FeatureMission, AnyStationCollects) {
  Seen seen;
  const auto registry = scripted(12.0, seen);
  auto scene = featureScene();
  scene.fleet[0].startPosition = world::Vec3(-20, 0, 1);
  scene.fleet.push_back(testing::unitAt("gcs2", world::UnitRole::GroundStation, {-3, 0, 1}));
  Mission mission(scene, Config::fromText(kFeatureMission, "features.ini"), registry);
  mission.run();
  const auto f = mission.summary().features;
  EXPECT_EQ(f.collected, 3u);
  ASSERT_TRUE(f.finishTime);
  EXPECT_TRUE(hasEvent(mission, "mission-end", "all features collected"));
  EXPECT_EQ(f.units[mission.unitIndex("gcs")].held, 0u);
  EXPECT_EQ(f.units[mission.unitIndex("gcs2")].held, 3u);
}

// Two stations that both receive the results count each feature once, at the first receipt
// (the mission runs on to its budget so that both receive them).
TEST(FeatureMission, AFeatureHeldByTwoStationsIsCollectedOnce) {
  Seen seen;
  const auto registry = scripted(12.0, seen);
  auto scene = featureScene();
  scene.fleet.push_back(testing::unitAt("gcs2", world::UnitRole::GroundStation, {-3, 0, 1}));
  const auto config = Config::fromText(kFeatureMission + "[features]\nend_when_collected = false\n",
                                       "features.ini");
  Mission mission(scene, config, registry);
  mission.run();
  const auto f = mission.summary().features;
  EXPECT_EQ(f.collected, 3u);
  EXPECT_EQ(f.units[mission.unitIndex("gcs")].held, 3u);
  EXPECT_EQ(f.units[mission.unitIndex("gcs2")].held, 3u);
  const auto& events = mission.events();
  EXPECT_EQ(std::count_if(events.begin(), events.end(),
                          [](const MissionEvent& e) { return e.kind == "feature-collected"; }),
            3);
}

TEST(FeatureMission, AnInspectionNeedsTheWholeInspectTimeInView) {
  Seen seen;
  const auto registry = scripted(12.0, seen);
  // The inspector is in view for less than 12 s: a 15 s inspection never completes.
  const auto config =
      Config::fromText(kFeatureMission + "[features]\ninspect_time = 15\n", "features.ini");
  Mission mission(featureScene(), config, registry);
  mission.run();
  const auto f = mission.summary().features;
  EXPECT_EQ(f.discovered, 3u);
  EXPECT_EQ(f.inspected, 0u);
  EXPECT_EQ(f.collected, 0u);
}

// The explorer promises a station meeting at `promise` s (from `replaceAt` on, at `replacement`
// s), flies off out of the station's 5 m range, comes back next to it at `returnAt` and leaves
// again at `leaveAt`.
class Promiser final : public agent::Strategy {
 public:
  Promiser(std::string name, double promise, double replaceAt, double replacement, double returnAt,
           double leaveAt)
      : name_(std::move(name)),
        promise_(promise),
        replaceAt_(replaceAt),
        replacement_(replacement),
        returnAt_(returnAt),
        leaveAt_(leaveAt) {}
  agent::AgentCommand decide(const agent::AgentView& view) override {
    agent::AgentCommand command;
    if (name_ != "e") return command;
    agent::AgentSetpoint setpoint;
    const bool back = view.time >= returnAt_ && view.time < leaveAt_;
    setpoint.position = back ? agent::Vec3(1.5, -1, 2) : agent::Vec3(6.5, -4, 4);
    command.setpoint = setpoint;
    command.stationMeetingTime = view.time < replaceAt_ ? promise_ : replacement_;
    return command;
  }

 private:
  std::string name_;
  double promise_, replaceAt_, replacement_, returnAt_, leaveAt_;
};

sim::FeatureSummary promises(double promise, double replaceAt, double replacement, double returnAt,
                             double leaveAt = 1e9) {
  agent::StrategyRegistry registry;
  registry.registerStrategy("scripted", [=](const agent::StrategyContext& context) {
    return std::make_unique<Promiser>(context.unitName, promise, replaceAt, replacement, returnAt,
                                      leaveAt);
  });
  const auto config = Config::fromText(kFeatureMission, "features.ini");
  Mission mission(featureScene(), config, registry);
  mission.run();  // 40 s: nothing is collected (no inspection)
  return mission.summary().features;
}

// Promised at 20 s, tolerance 10 s: linked with the station within [10, 30] s is on time, first
// linked after 30 s late, never linked missed; a promise replaced before its window opens is
// early when the two met meanwhile, else rescheduled; one still open at the end is not counted.
TEST(FeatureMission, PunctualityComparesPromisedStationMeetingsWithLinks) {
  // Linked from about 14 to 17 s only: not at 20 s itself, but within the tolerance.
  const auto onTime = promises(20, 1e9, 0, 12, 17);
  EXPECT_EQ(onTime.promisesOnTime, 1u);
  EXPECT_EQ(onTime.promisesLate + onTime.promisesMissed + onTime.promisesRescheduled, 0u);
  const auto late = promises(20, 1e9, 0, 31);
  EXPECT_EQ(late.promisesLate, 1u);
  EXPECT_EQ(late.promisesOnTime + late.promisesMissed + late.promisesRescheduled, 0u);
  const auto missed = promises(20, 1e9, 0, 1e9);
  EXPECT_EQ(missed.promisesMissed, 1u);
  EXPECT_EQ(missed.promisesOnTime + missed.promisesLate + missed.promisesRescheduled, 0u);
  const auto rescheduled = promises(30, 5, 60, 1e9);
  EXPECT_EQ(rescheduled.promisesRescheduled, 1u);
  EXPECT_EQ(rescheduled.promisesOnTime + rescheduled.promisesEarly + rescheduled.promisesLate +
                rescheduled.promisesMissed,
            0u);
  // Out at the start, back at the station from about 14 s, the promise of 30 s replaced at 16 s.
  const auto early = promises(30, 16, 60, 12);
  EXPECT_EQ(early.promisesEarly, 1u);
  EXPECT_EQ(
      early.promisesOnTime + early.promisesLate + early.promisesMissed + early.promisesRescheduled,
      0u);
}

// [features] priority_boxes: the features inside the named boxes are high priority: explorers'
// detections say so, the summary counts their collection apart.
TEST(FeatureMission, FeaturesInPriorityBoxesAreReportedAndCountedApart) {
  world::Scenario scene = featureScene();
  world::OrientedBox left;  // around feature 0 (y = -1) only
  left.name = "left";
  left.center = world::Vec3(10, -1, 4);
  left.size = world::Vec3(1, 1, 1);
  scene.boxes.push_back(left);
  Seen seen;
  const auto registry = scripted(12.0, seen);
  Mission mission(
      scene, Config::fromText(kFeatureMission + "[features]\npriority_boxes = left\n", "p.ini"),
      registry);
  mission.run();
  const auto& f = mission.summary().features;
  ASSERT_EQ(seen.detected["e"].size(), 3u);
  for (const auto& d : seen.detected["e"])
    EXPECT_EQ(d.highPriority, d.id == 0) << d.id;
  EXPECT_EQ(f.highPriority, (std::vector<uint8_t>{1, 0, 0}));
  EXPECT_EQ(seen.urgentBoxes, (std::vector<bool>{false, true}));  // "face", "left"
  EXPECT_EQ(f.priorityTotal, 1u);
  EXPECT_EQ(f.priorityCollected, 1u);
  ASSERT_TRUE(f.priorityFinishTime);
  EXPECT_DOUBLE_EQ(*f.priorityFinishTime, f.collectedAt[0]);
  EXPECT_MENTIONS(formatSummary(mission.summary()),
                  "priority    1 high-priority features: collected 1");

  // Without the key nothing is high priority and the summary has no priority line.
  Seen plain;
  const auto plainRegistry = scripted(12.0, plain);
  Mission without(scene, Config::fromText(kFeatureMission, "p.ini"), plainRegistry);
  without.run();
  EXPECT_EQ(without.summary().features.priorityTotal, 0u);
  EXPECT_FALSE(without.summary().features.priorityFinishTime);
  for (const auto& d : plain.detected["e"])
    EXPECT_FALSE(d.highPriority);
  EXPECT_EQ(formatSummary(without.summary()).find("priority    "), std::string::npos);

  // A box that holds no feature cannot be an urgent area.
  world::OrientedBox far;
  far.name = "far";
  far.center = world::Vec3(0, 30, 4);
  far.size = world::Vec3(1, 1, 1);
  scene.boxes.push_back(far);
  const auto config =
      Config::fromText(kFeatureMission + "[features]\npriority_boxes = far\n", "p.ini");
  const auto message = coinspect::testing::messageOf([&] { Mission(scene, config, registry); });
  EXPECT_MENTIONS(message, "p.ini");
  EXPECT_MENTIONS(message, "priority_boxes");
  EXPECT_MENTIONS(message, "'far' holds no feature");
}

// Heterogeneous explorers: each detects within its own range, which its teammates know. The
// explorer hovers 3.6 to 4.6 m from the three features.
TEST(FeatureMission, EachExplorerDetectsWithinItsOwnRange) {
  for (const auto& [range, expected] : {std::pair<double, size_t>{3.0, 0}, {6.0, 3}}) {
    Seen seen;
    const auto registry = scripted(12.0, seen);
    const auto config = Config::fromText(
        kFeatureMission +
            "[features]\ndetect_range = 5\nexplorer_ranges = " + std::to_string(range) + "\n",
        "features.ini");
    Mission mission(featureScene(), config, registry);
    mission.run();
    EXPECT_EQ(mission.summary().features.discovered, expected) << range;
    EXPECT_EQ(seen.detectRanges, (std::vector<double>{0.0, range, 0.0}));
  }
}

// `detect_line_of_sight = false` is the reference code's detector: a feature on the far face of the
// wall (4.6 m from the explorer, in its field of view) is detected through the wall.
TEST(FeatureMission, WithoutTheLineOfSightTestAFeatureBehindTheWallIsDetected) {
  for (const bool lineOfSight : {true, false}) {
    Seen seen;
    const auto registry = scripted(12.0, seen);
    auto scene = featureScene();
    auto points = scene.interestPoints.points();
    world::InterestPoint behind;
    behind.position = world::Vec3(11.0, -1.0, 4.0);
    behind.normal = world::Vec3(1, 0, 0);
    points.push_back(behind);
    scene.interestPoints = world::InterestPointSet(points);
    const auto config = Config::fromText(kFeatureMission + "[features]\ndetect_line_of_sight = " +
                                             (lineOfSight ? "true" : "false") + "\n",
                                         "features.ini");
    Mission mission(scene, config, registry);
    mission.run();
    EXPECT_EQ(mission.summary().features.discovered, lineOfSight ? 3u : 4u) << lineOfSight;
  }
}

TEST(FeatureMission, BadFeatureKeysAreErrorsNamingTheKey) {
  Seen seen;
  const auto registry = scripted(12.0, seen);
  const auto expectError = [&](const std::string& text, const std::string& key) {
    const auto config = Config::fromText(text, "bad.ini");
    const auto message =
        coinspect::testing::messageOf([&] { Mission(featureScene(), config, registry); });
    EXPECT_MENTIONS(message, "bad.ini");
    EXPECT_MENTIONS(message, key);
  };
  expectError(kFeatureMission + "[features]\ninspect_score = 0\n", "inspect_score");
  expectError(kFeatureMission + "[features]\ndetect_half_yaw = 200\n", "detect_half_yaw");
  expectError(kFeatureMission + "[features]\ndetect_range = -1\n", "detect_range");
  expectError(kFeatureMission + "[features]\ndetect_line_of_sight = maybe\n",
              "detect_line_of_sight");
  expectError(kFeatureMission + "[features]\nmeeting_gap = nan\n", "meeting_gap");
  expectError(kFeatureMission + "[features]\npunctuality_tolerance = -1\n",
              "punctuality_tolerance");
  expectError(kFeatureMission + "[features]\npriority_boxes = face roof\n", "priority_boxes");
  expectError(kFeatureMission + "[features]\nexplorer_ranges = 5 5\n", "explorer_ranges");
  expectError(kFeatureMission + "[features]\nexplorer_ranges = 0\n", "explorer_ranges");
  expectError(kFeatureMission + "[features]\nexplorer_ranges = far\n", "explorer_ranges");
  expectError("[mission]\nobjective = score\n[strategy]\nname = scripted\n", "objective");
  expectError("[mission]\n[features]\ninspect_time = 2\n[strategy]\nname = scripted\n",
              "[features]");
}

}  // namespace
}  // namespace coinspect::sim
