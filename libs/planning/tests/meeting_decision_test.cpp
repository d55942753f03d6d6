#include "coinspect/planning/meeting_decision.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <vector>

#include "coinspect/core/random.h"
#include "coinspect/testing/input_errors.h"

namespace coinspect::planning {
namespace {

using mapping::CellState;
using mapping::Index3;

constexpr double kInf = std::numeric_limits<double>::infinity();

MeetingSpace openSpace() {
  MeetingSpace space;
  space.isFree = [](const Vec3&) { return true; };
  space.lineOfSight = [](const Vec3&, const Vec3&) { return true; };
  return space;
}

MeetingBox bigBox() {
  return {Vec3::Constant(-100.0), Vec3::Constant(100.0)};
}

// The reference's sampling without the cap on the sample count, to see every node kept.
MeetingSamplingOptions uncapped() {
  MeetingSamplingOptions options;
  options.maxSamples = 1000000;
  return options;
}

HoverWindow window(const Vec3& position, double start, double end = kOpenWindowEnd) {
  HoverWindow hover;
  hover.position = position;
  hover.start = start;
  hover.end = end;
  return hover;
}

InspectorPlan plan(int id, std::vector<HoverWindow> poses) {
  InspectorPlan inspector;
  inspector.id = id;
  inspector.poses = std::move(poses);
  return inspector;
}

// ---------------------------------------------------------------------------------------------
// SampleLOS

TEST(MeetingSampling, KeepsGridNodesBetweenTheSeparationAndRangeMinusMargin) {
  const Vec3 pose(1.0, 2.0, 3.0);
  const MeetingSamplingOptions options = uncapped();  // 5 m range, 1 m margin and separation
  const std::vector<Vec3> samples = sampleMeetingPoints(pose, bigBox(), openSpace(), options);
  // Count the nodes of the +-range cube the rule keeps.
  size_t expected = 0;
  for (int i = -13; i <= 13; ++i) {
    for (int j = -13; j <= 13; ++j) {
      for (int k = -13; k <= 13; ++k) {
        const double d = 0.4 * std::sqrt(double(i * i + j * j + k * k));
        if (d <= 4.0 + 1e-9 && d >= 1.0 - 1e-9 && d <= 5.0) ++expected;
      }
    }
  }
  EXPECT_EQ(samples.size(), expected);
  for (const Vec3& sample : samples) {
    const double d = (sample - pose).norm();
    EXPECT_LE(d, 4.0 + 1e-9);
    EXPECT_GE(d, 1.0 - 1e-9);
    const Vec3 steps = (sample - pose) / 0.4;
    EXPECT_NEAR((steps - steps.array().round().matrix()).norm(), 0.0, 1e-9);  // on the grid
  }
}

TEST(MeetingSampling, StaysInsideTheBox) {
  const Vec3 pose(0.0, 0.0, 0.0);
  const MeetingSamplingOptions options = uncapped();
  const size_t all = sampleMeetingPoints(pose, bigBox(), openSpace(), options).size();
  const MeetingBox box{Vec3(-10.0, -10.0, -1.0), Vec3(10.0, 0.0, 10.0)};  // y <= 0, z >= -1
  const std::vector<Vec3> samples = sampleMeetingPoints(pose, box, openSpace(), options);
  ASSERT_FALSE(samples.empty());
  EXPECT_LT(samples.size(), all / 2 + all / 10);
  for (const Vec3& sample : samples) {
    EXPECT_LE(sample.y(), 1e-9);
    EXPECT_GE(sample.z(), -1.0 - 1e-9);
  }
}

TEST(MeetingSampling, AsksTheFreeAndLineOfSightQueries) {
  const Vec3 pose(0.0, 0.0, 0.0);
  const MeetingSamplingOptions options = uncapped();
  const std::vector<Vec3> all = sampleMeetingPoints(pose, bigBox(), openSpace(), options);
  // A wall at x = 0.2 hides every node with x >= 0.4 from the pose; a floor at z = -2 is not
  // free below it.
  MeetingSpace space;
  space.isFree = [](const Vec3& p) { return p.z() > -2.0; };
  space.lineOfSight = [](const Vec3& a, const Vec3& b) {
    return !((a.x() - 0.2) * (b.x() - 0.2) < 0.0);
  };
  const std::vector<Vec3> samples = sampleMeetingPoints(pose, bigBox(), space, options);
  const size_t expected = std::count_if(all.begin(), all.end(),
                                        [](const Vec3& p) { return p.x() < 0.2 && p.z() > -2.0; });
  EXPECT_EQ(samples.size(), expected);
  EXPECT_GT(samples.size(), all.size() / 3);
  EXPECT_LT(samples.size(), all.size() * 2 / 3);
  for (const Vec3& sample : samples) {
    EXPECT_LT(sample.x(), 0.2);
    EXPECT_GT(sample.z(), -2.0);
  }
}

TEST(MeetingSampling, ThinsUniformlyByIndex) {
  const Vec3 pose(0.0, 0.0, 0.0);
  MeetingSamplingOptions options = uncapped();
  const std::vector<Vec3> all = sampleMeetingPoints(pose, bigBox(), openSpace(), options);
  ASSERT_GT(all.size(), 1000u);
  EXPECT_EQ(sampleMeetingPoints(pose, bigBox(), openSpace(), {}).size(), 1000u);  // the default
  options.maxSamples = 7;
  const std::vector<Vec3> thinned = sampleMeetingPoints(pose, bigBox(), openSpace(), options);
  ASSERT_EQ(thinned.size(), 7u);
  for (size_t i = 0; i < thinned.size(); ++i)
    EXPECT_EQ(thinned[i], all[i * all.size() / 7]) << i;
  options.maxSamples = 0;
  EXPECT_MENTIONS(
      testing::messageOf([&] { sampleMeetingPoints(pose, bigBox(), openSpace(), options); }),
      "maxSamples");
}

// A 10 m cube of 0.2 m cells, free, with an occupied wall at x in [6.0, 6.2) and unknown space
// at z >= 9.
VoxelGrid walledGrid() {
  VoxelGrid grid(Vec3::Zero(), 0.2, Index3(50, 50, 50), CellState::Free);
  for (int y = 0; y < 50; ++y) {
    for (int z = 0; z < 50; ++z) {
      grid.set(Index3(30, y, z), CellState::Occupied);
      for (int x = 0; x < 50 && z >= 45; ++x)
        grid.set(Index3(x, y, z), CellState::Unknown);
    }
  }
  return grid;
}

TEST(MeetingSampling, VoxelGridSpaceBlocksOccupiedUnknownAndOutside) {
  VoxelGrid grid = walledGrid();
  const MeetingSpace space = voxelGridMeetingSpace(grid, 0.0);
  const Vec3 pose(5.1, 5.1, 5.1);
  EXPECT_TRUE(space.isFree(pose));
  EXPECT_FALSE(space.isFree(Vec3(6.1, 5.1, 5.1)));   // occupied
  EXPECT_FALSE(space.isFree(Vec3(5.1, 5.1, 9.5)));   // unknown
  EXPECT_FALSE(space.isFree(Vec3(-0.5, 5.1, 5.1)));  // outside the grid
  EXPECT_TRUE(space.lineOfSight(pose, Vec3(5.9, 3.0, 7.0)));
  EXPECT_FALSE(space.lineOfSight(pose, Vec3(7.0, 5.1, 5.1)));  // through the wall
  EXPECT_FALSE(space.lineOfSight(pose, Vec3(5.1, 5.1, 9.3)));  // into the unknown
  // The wall cell is only grazed by a steep diagonal: half-cell steps still land in it.
  EXPECT_FALSE(space.lineOfSight(Vec3(5.99, 5.1, 5.1), Vec3(6.21, 5.3, 5.1)));

  const std::vector<Vec3> samples = sampleMeetingPoints(pose, bigBox(), space, {});
  ASSERT_FALSE(samples.empty());
  for (const Vec3& sample : samples) {
    EXPECT_LT(sample.x(), 6.0);
    EXPECT_LT(sample.z(), 9.0);
  }

  EXPECT_MENTIONS(testing::messageOf([&] { voxelGridMeetingSpace(grid, 0.5); }), "clearance");
  grid.computeClearance(2.0, true);
  const MeetingSpace clear = voxelGridMeetingSpace(grid, 0.5);
  EXPECT_FALSE(clear.isFree(Vec3(5.7, 5.1, 5.1)));  // 0.4 m from the wall's cell centres
  EXPECT_TRUE(clear.isFree(Vec3(5.5, 5.1, 5.1)));   // 0.6 m
  const MeetingSpace clearSight = voxelGridMeetingSpace(grid, 0.0, 0.5);
  EXPECT_TRUE(clearSight.lineOfSight(pose, Vec3(5.5, 5.1, 5.1)));
  EXPECT_FALSE(clearSight.lineOfSight(pose, Vec3(5.7, 5.1, 5.1)));
}

TEST(MeetingSampling, ThePartnersOwnBodyInTheMapBlocksNoSightLine) {
  // The partner hovers 0.9 m off the wall; the map holds its body as occupied cells (a UAV out
  // of link range is not filtered from scans).
  VoxelGrid grid = walledGrid();
  const Vec3 pose(5.1, 5.1, 5.1);
  for (int z = 24; z <= 26; ++z)
    for (int y = 24; y <= 26; ++y)
      for (int x = 24; x <= 26; ++x)
        grid.set(Index3(x, y, z), CellState::Occupied);
  const MeetingSpace space = voxelGridMeetingSpace(grid, 0.0);
  MeetingSamplingOptions options;
  EXPECT_TRUE(sampleMeetingPoints(pose, bigBox(), space, options).empty());  // sight ends in it
  options.partnerRadius = 0.8;  // past the body, short of the wall
  const std::vector<Vec3> samples = sampleMeetingPoints(pose, bigBox(), space, options);
  EXPECT_GT(samples.size(), 100u);
  for (const Vec3& sample : samples)
    EXPECT_LT(sample.x(), 6.0);  // none seen through the wall
  options.partnerRadius = -0.1;
  EXPECT_MENTIONS(testing::messageOf([&] { sampleMeetingPoints(pose, bigBox(), space, options); }),
                  "partnerRadius");
}

// ---------------------------------------------------------------------------------------------
// OptMeet

TEST(MeetingRoute, EvaluatesAHandComputedTimeline) {
  ExplorerState explorer;  // at the origin, now = 0
  const std::vector<InspectorPlan> inspectors = {
      plan(7, {window(Vec3(6, 0, 0), 10.0, 12.0), window(Vec3(20, 0, 0), 30.0)}),
      plan(8, {window(Vec3(4, 10, 0), 0.0)}),
  };
  const std::vector<InspectorMeetingPoints> points = {
      {{Vec3(4, 0, 0)}, {Vec3(18, 0, 0)}},
      {{Vec3(4, 8, 0)}},
  };
  MeetingRouteOptions options;  // t_q 3 s, 2 m/s, 1 m/s^2
  const MeetingRoute route =
      evaluateMeetingRoute(explorer, inspectors, points, {0, 1}, {{0, 0}, {0, 0}}, options);
  ASSERT_EQ(route.stops.size(), 2u);
  // 4 m in 4 s, then wait for the window [10, 12].
  EXPECT_DOUBLE_EQ(route.stops[0].arrival, 4.0);
  EXPECT_DOUBLE_EQ(route.stops[0].meetingTime, 10.0);
  EXPECT_DOUBLE_EQ(route.stops[0].explorerWait, 6.0);
  EXPECT_DOUBLE_EQ(route.stops[0].inspectorWait, 0.0);
  // Leaves at 10, 8 m in 4 + 2 s; the second inspector idles since 0 + t_q.
  EXPECT_DOUBLE_EQ(route.stops[1].arrival, 16.0);
  EXPECT_DOUBLE_EQ(route.stops[1].inspectorWait, 13.0);
  EXPECT_DOUBLE_EQ(route.cost, 4.0 + 6.0 + 6.0 + 13.0);
  EXPECT_TRUE(route.feasible());

  // The other way round the first window is missed: sqrt(80) m in 6.47 s, 8 m in 6 s.
  const MeetingRoute late =
      evaluateMeetingRoute(explorer, inspectors, points, {1, 0}, {{0, 0}, {0, 0}}, options);
  EXPECT_FALSE(late.stops[1].feasible);
  EXPECT_EQ(late.cost, kInf);

  // Idle time before now is not charged: at now = 20 the wait counts from 20.
  explorer.now = 20.0;
  const MeetingRoute laterStart =
      evaluateMeetingRoute(explorer, inspectors, points, {1}, {{0, 0}}, options);
  EXPECT_DOUBLE_EQ(laterStart.stops[0].inspectorWait, laterStart.stops[0].arrival - 20.0);
}

// The oracle: the route's timeline written out again, independently of meeting_route.cpp.
// Returns the cost (+infinity when a window is missed) and fills the meeting times.
double oracleCost(const ExplorerState& explorer, const std::vector<InspectorPlan>& inspectors,
                  const std::vector<InspectorMeetingPoints>& points, const std::vector<int>& order,
                  const std::vector<MeetingPick>& picks, double tq, const TravelLimits& limits,
                  std::vector<double>* meetingTimes = nullptr) {
  Vec3 at = explorer.position;
  double clock = explorer.now, cost = 0.0;
  if (meetingTimes) meetingTimes->clear();
  for (size_t k = 0; k < order.size(); ++k) {
    const HoverWindow& w = inspectors[order[k]].poses[picks[k].pose];
    const Vec3& point = points[order[k]][picks[k].pose][picks[k].sample];
    const double travel = travelTime((point - at).norm(), limits);
    const double arrival = clock + travel;
    if (arrival > w.end) return kInf;
    const double wait = std::max(0.0, w.start - arrival);
    double inspectorWait = 0.0;
    if (std::isinf(w.end))
      inspectorWait = std::max(0.0, arrival - std::max(explorer.now, w.start + tq));
    cost += travel + wait + inspectorWait;
    clock = arrival + wait;
    at = point;
    if (meetingTimes) meetingTimes->push_back(clock);
  }
  return cost;
}

struct OracleRoute {
  double cost = kInf;
  std::vector<MeetingPick> picks;
};

// Every combination of one candidate per inspector of `order`; the first of equal costs.
OracleRoute bruteForce(const ExplorerState& explorer, const std::vector<InspectorPlan>& inspectors,
                       const std::vector<InspectorMeetingPoints>& points,
                       const std::vector<int>& order, double tq, const TravelLimits& limits) {
  std::vector<std::vector<MeetingPick>> pools;
  for (const int i : order) {
    pools.emplace_back();
    for (size_t p = 0; p < points[i].size(); ++p) {
      for (size_t s = 0; s < points[i][p].size(); ++s)
        pools.back().push_back({int(p), int(s)});
    }
  }
  OracleRoute best;
  std::vector<MeetingPick> picks(order.size());
  std::function<void(size_t)> recurse = [&](size_t k) {
    if (k == order.size()) {
      const double cost = oracleCost(explorer, inspectors, points, order, picks, tq, limits);
      if (cost < best.cost) best = {cost, picks};
      return;
    }
    for (const MeetingPick& pick : pools[k]) {
      picks[k] = pick;
      recurse(k + 1);
    }
  };
  recurse(0);
  return best;
}

// Random instances: each inspector has 2-3 poses with `minSamples` to `maxSamples` samples each,
// closed windows of t_q seconds, then an open last one. Often the explorer has to wait, or an
// order misses a closed window and must use a later pose.
struct RouteInstance {
  ExplorerState explorer;
  std::vector<InspectorPlan> inspectors;
  std::vector<InspectorMeetingPoints> points;
};

RouteInstance randomRouteInstance(uint64_t seed, int inspectorCount, int minSamples = 3,
                                  int maxSamples = 5) {
  Rng rng(seed);
  RouteInstance instance;
  instance.explorer.position = Vec3(rng.uniform(-5, 5), rng.uniform(-5, 5), 0.0);
  instance.explorer.now = 10.0;
  for (int i = 0; i < inspectorCount; ++i) {
    InspectorPlan inspector;
    inspector.id = i;
    InspectorMeetingPoints points;
    const int poses = 2 + int(rng.below(2));
    double t = rng.uniform(0.0, 20.0);
    Vec3 at(rng.uniform(-15, 15), rng.uniform(-15, 15), rng.uniform(0, 5));
    for (int p = 0; p < poses; ++p) {
      const bool last = p + 1 == poses;
      inspector.poses.push_back(window(at, t, last ? kOpenWindowEnd : t + 3.0));
      points.emplace_back();
      const int samples = minSamples + int(rng.below(maxSamples - minSamples + 1));
      for (int s = 0; s < samples; ++s)
        points.back().push_back(at + Vec3(rng.uniform(-4, 4), rng.uniform(-4, 4), 0.0));
      at += Vec3(rng.uniform(-6, 6), rng.uniform(-6, 6), 0.0);
      t += 3.0 + rng.uniform(1.0, 6.0);
    }
    instance.inspectors.push_back(inspector);
    instance.points.push_back(points);
  }
  return instance;
}

// Runs the GA on random instances, both orders of the inspectors, and counts how often it
// misses the brute-force optimum; checks the reported cost against the oracle's evaluation of
// its picks. `costs` receives the GA's cost of every run.
int missedOptima(const MeetingRouteOptions& options, int inspectorCount, int minSamples,
                 int maxSamples, int instances, std::vector<double>& costs) {
  int missed = 0;
  for (int instanceSeed = 1; instanceSeed <= instances; ++instanceSeed) {
    const RouteInstance instance =
        randomRouteInstance(instanceSeed, inspectorCount, minSamples, maxSamples);
    std::vector<int> forward(inspectorCount), backward;
    for (int i = 0; i < inspectorCount; ++i)
      forward[i] = i;
    backward.assign(forward.rbegin(), forward.rend());
    for (const std::vector<int>& order : {forward, backward}) {
      const double optimum = bruteForce(instance.explorer, instance.inspectors, instance.points,
                                        order, options.inspectionTime, options.explorer)
                                 .cost;
      const MeetingRoute route = optimiseMeetingRoute(instance.explorer, instance.inspectors,
                                                      instance.points, order, options, 99);
      EXPECT_TRUE(std::isfinite(optimum));  // the last poses' windows never close
      std::vector<MeetingPick> picks;
      for (const MeetingStop& stop : route.stops)
        picks.push_back(stop.pick);
      EXPECT_NEAR(oracleCost(instance.explorer, instance.inspectors, instance.points, order, picks,
                             options.inspectionTime, options.explorer),
                  route.cost, 1e-9);
      EXPECT_GE(route.cost, optimum - 1e-9);
      if (route.cost > optimum + 1e-9) ++missed;
      costs.push_back(route.cost);
    }
  }
  return missed;
}

// The reference's GA alone (no polish) on instances with 1-2 samples per pose (at most 6
// candidates per inspector): its initial population and crossovers cover them.
TEST(MeetingRoute, GeneticAlgorithmFindsTheBruteForceOptimumOfTinyInstances) {
  MeetingRouteOptions options;
  options.ga.polishSweeps = 0;
  std::vector<double> costs;
  EXPECT_EQ(missedOptima(options, 2, 1, 2, 40, costs), 0);
  EXPECT_EQ(missedOptima(options, 3, 1, 2, 40, costs), 0);
}

// On 3 inspectors with 3-5 samples per pose (up to 15 candidates each), the reference's GA often
// stops short (it tries few of the candidates); the polish (coordinate descent from the GA's best
// and from a greedy route) almost always reaches the optimum, and is never worse.
TEST(MeetingRoute, PolishReachesTheBruteForceOptimumAlmostAlways) {
  MeetingRouteOptions raw;
  raw.ga.polishSweeps = 0;
  std::vector<double> rawCosts, polishedCosts;
  const int rawMissed = missedOptima(raw, 3, 3, 5, 40, rawCosts);
  const int polishedMissed = missedOptima(MeetingRouteOptions{}, 3, 3, 5, 40, polishedCosts);
  EXPECT_LE(polishedMissed, 2);  // 1 of these 80 runs
  EXPECT_LT(polishedMissed, rawMissed);
  ASSERT_EQ(rawCosts.size(), polishedCosts.size());
  for (size_t i = 0; i < rawCosts.size(); ++i)
    EXPECT_LE(polishedCosts[i], rawCosts[i] + 1e-9) << i;
}

TEST(MeetingRoute, MissedWindowsCostInfinity) {
  ExplorerState explorer;
  explorer.position = Vec3(-30, 0, 0);
  explorer.now = 0.0;
  // The only pose is 30 m away (17 s) and left at t = 5.
  const std::vector<InspectorPlan> inspectors = {plan(1, {window(Vec3(0, 0, 0), 2.0, 5.0)})};
  const std::vector<InspectorMeetingPoints> points = {{{Vec3(-2, 0, 0), Vec3(0, 2, 0)}}};
  const MeetingRoute route =
      optimiseMeetingRoute(explorer, inspectors, points, {0}, MeetingRouteOptions{}, 3);
  EXPECT_FALSE(route.feasible());
  EXPECT_EQ(route.cost, kInf);

  // An inspector without any candidate cannot be met either.
  const std::vector<InspectorMeetingPoints> none = {{{}}};
  EXPECT_FALSE(
      optimiseMeetingRoute(explorer, inspectors, none, {0}, MeetingRouteOptions{}, 3).feasible());

  MeetingProblem problem;
  problem.explorer = explorer;
  problem.inspectors = inspectors;
  problem.features = {{11, Vec3(1, 1, 1), Vec3(1, 0, 0)}};
  problem.explorationFinished = true;
  const MeetingDecision decision = decideMeetings(problem, points, MeetingOptions{});
  EXPECT_EQ(decision.choice, MeetingChoice::NoFeasibleMeeting);
  EXPECT_TRUE(decision.meetings.empty());
  EXPECT_EQ(decision.candidates, 1);
  EXPECT_EQ(decision.feasibleCandidates, 0);
}

TEST(MeetingRoute, TheOrderChangesWhereAndAtWhatCost) {
  ExplorerState explorer;  // origin, now = 0
  // A hovers at (6, 0, 0) until t = 5, then moves to (30, 0, 0) from t = 20; B idles at -6.
  const std::vector<InspectorPlan> inspectors = {
      plan(1, {window(Vec3(6, 0, 0), 0.0, 5.0), window(Vec3(30, 0, 0), 20.0)}),
      plan(2, {window(Vec3(-6, 0, 0), 0.0)}),
  };
  const std::vector<InspectorMeetingPoints> points = {
      {{Vec3(2, 0, 0)}, {Vec3(26, 0, 0)}},
      {{Vec3(-2, 0, 0)}},
  };
  const MeetingRouteOptions options;
  const MeetingRoute ab = optimiseMeetingRoute(explorer, inspectors, points, {0, 1}, options, 1);
  const MeetingRoute ba = optimiseMeetingRoute(explorer, inspectors, points, {1, 0}, options, 1);
  ASSERT_TRUE(ab.feasible() && ba.feasible());
  const double t2 = 2.0 * std::sqrt(2.0);  // 2 m
  // A at (2, 0, 0) first; B 4 m later (4 s), idle since t_q = 3.
  EXPECT_EQ(ab.stops[0].pick.pose, 0);
  EXPECT_NEAR(ab.cost, t2 + 4.0 + (t2 + 4.0 - 3.0), 1e-9);
  // B first makes A's first window unreachable (t2 + 4 > 5): 28 m to A's last pose, in 16 s.
  EXPECT_EQ(ba.stops[1].pick.pose, 1);
  EXPECT_NEAR(ba.cost, t2 + 16.0 + (20.0 - (t2 + 16.0)), 1e-9);
  EXPECT_LT(ab.cost, ba.cost);
}

// ---------------------------------------------------------------------------------------------
// MVRP

// Features at x = 4, 8, 9, -1, 14 (ids 100..104), inspected from y = 0; those at `urgent` x are
// high priority.
std::vector<PendingFeature> featuresOnALine(const std::vector<double>& urgent) {
  std::vector<PendingFeature> features;
  for (const double x : {4.0, 8.0, 9.0, -1.0, 14.0}) {
    PendingFeature feature;
    feature.id = 100 + static_cast<int64_t>(features.size());
    feature.position = Vec3(x, 1.0, 0.0);
    feature.inspectFrom = Vec3(x, 0.0, 0.0);
    feature.highPriority = std::find(urgent.begin(), urgent.end(), x) != urgent.end();
    features.push_back(feature);
  }
  return features;
}

TEST(MeetingAllocation, RoundRobinNearestNeighbourOnAHandMadeInstance) {
  // Travel times at 2 m/s, 1 m/s^2: 1 m -> 2 s, 5 m -> 4.5 s, 10 m -> 7 s.
  const std::vector<InspectorPlan> inspectors = {
      plan(1, {window(Vec3(0, 0, 0), 0.0)}), plan(2, {window(Vec3(10, 0, 0), 20.0)}),
      plan(3, {window(Vec3(50, 0, 0), 5.0)}),  // not met
  };
  const std::vector<PendingFeature> features = featuresOnALine({});
  const FeatureAllocation allocation =
      allocateFeatures(inspectors, {0, 1}, {12.0, 15.0}, features, 10.0, AllocationModel{});
  ASSERT_EQ(allocation.agents.size(), 2u);
  const InspectorAssignment& first = allocation.agents[0];
  const InspectorAssignment& second = allocation.agents[1];
  // Inspector 0 starts at its meeting (12), inspector 1 when its own plan ends (20 + 3).
  EXPECT_DOUBLE_EQ(first.startTime, 12.0);
  EXPECT_DOUBLE_EQ(second.startTime, 23.0);
  // Turns: 0 takes -1, 1 takes 9, 0 takes 4 (from -1), 1 takes 8, 0 takes 14.
  EXPECT_EQ(first.features, (std::vector<int>{3, 0, 4}));
  EXPECT_EQ(second.features, (std::vector<int>{2, 1}));
  EXPECT_DOUBLE_EQ(first.travelTime, 2.0 + 4.5 + 7.0);
  EXPECT_DOUBLE_EQ(first.finishTime, 12.0 + 13.5 + 9.0);
  EXPECT_DOUBLE_EQ(second.travelTime, 4.0);
  EXPECT_DOUBLE_EQ(second.finishTime, 23.0 + 4.0 + 6.0);
  EXPECT_DOUBLE_EQ(allocation.rightAxis, 34.5);
  EXPECT_DOUBLE_EQ(allocation.agentCost, 13.5 + (4.0 + 1.5));
  // Inspector 2 idles from max(now = 10, 5 + 3).
  EXPECT_DOUBLE_EQ(allocation.othersCost, 34.5 - 10.0);
  EXPECT_DOUBLE_EQ(allocation.cost(), 19.0 + 24.5);

  EXPECT_MENTIONS(testing::messageOf([&] {
                    allocateFeatures(inspectors, {0, 0}, {1.0, 2.0}, features, 0.0, {});
                  }),
                  "repeated");
}

// Same instance with the farthest features (8 and 14) marked high priority: they are taken
// first, whatever is nearer, then the rest by nearest neighbour.
TEST(MeetingAllocation, HighPriorityFeaturesAreTakenFirst) {
  const std::vector<InspectorPlan> inspectors = {plan(1, {window(Vec3(0, 0, 0), 0.0)}),
                                                 plan(2, {window(Vec3(10, 0, 0), 20.0)})};
  const std::vector<PendingFeature> features = featuresOnALine({8.0, 14.0});
  const FeatureAllocation allocation =
      allocateFeatures(inspectors, {0, 1}, {12.0, 15.0}, features, 10.0, AllocationModel{});
  // Turns: 0 takes 8 (urgent, nearest of 8 and 14), 1 takes 14 (the last urgent one); then
  // 0 takes 9 (from 8), 1 takes 4 (from 14, nearer than -1), 0 takes -1.
  EXPECT_EQ(allocation.agents[0].features, (std::vector<int>{1, 2, 3}));
  EXPECT_EQ(allocation.agents[1].features, (std::vector<int>{4, 0}));
}

// ---------------------------------------------------------------------------------------------
// The decision

MeetingProblem oneIdleInspector(const Vec3& explorerAt) {
  MeetingProblem problem;
  problem.explorer.position = explorerAt;
  problem.explorer.now = 100.0;
  problem.inspectors = {plan(4, {window(Vec3(0, 0, 2), 0.0)})};
  problem.features = {{21, Vec3(0.5, 1, 2), Vec3(0.5, 0, 2)}};
  return problem;
}

TEST(MeetingDecision, SkipsACostlyMeetingWhileExploringButMeetsWhenFinished) {
  const MeetingBox box = bigBox();
  const MeetingSpace space = openSpace();
  MeetingProblem far = oneIdleInspector(Vec3(60, 0, 2));
  const MeetingDecision skip = decideMeetings(far, box, space, MeetingOptions{});
  EXPECT_EQ(skip.choice, MeetingChoice::NoMeeting);
  EXPECT_TRUE(skip.meetings.empty());
  EXPECT_LT(skip.noMeetingCost, skip.meetingCost);

  far.explorationFinished = true;
  const MeetingDecision forced = decideMeetings(far, box, space, MeetingOptions{});
  ASSERT_EQ(forced.choice, MeetingChoice::Meet);
  ASSERT_EQ(forced.meetings.size(), 1u);
  EXPECT_EQ(forced.meetings[0].inspectorId, 4);
  EXPECT_EQ(forced.meetings[0].featureIds, (std::vector<int64_t>{21}));
  // Its cost grows with the distance flown: the sample nearest to the explorer.
  double nearest = kInf;
  for (const Vec3& sample : sampleMeetingPoints(Vec3(0, 0, 2), box, space, {}))
    nearest = std::min(nearest, (sample - far.explorer.position).norm());
  EXPECT_NEAR((forced.meetings[0].point - far.explorer.position).norm(), nearest, 1e-9);
  EXPECT_DOUBLE_EQ(forced.meetingCost, skip.meetingCost);

  // Close by, meeting is worth it even while exploring.
  const MeetingDecision near =
      decideMeetings(oneIdleInspector(Vec3(3, 0, 2)), box, space, MeetingOptions{});
  EXPECT_EQ(near.choice, MeetingChoice::Meet);
  EXPECT_LT(near.meetingCost, near.noMeetingCost);

  // Nothing to hand over: no meeting, even when finished.
  MeetingProblem empty = far;
  empty.features.clear();
  EXPECT_EQ(decideMeetings(empty, box, space, MeetingOptions{}).choice, MeetingChoice::NoMeeting);
}

// `inspectorCount` inspectors with 2-3 poses, `featureCount` features spread around them.
MeetingProblem teamProblem(uint64_t seed, int inspectorCount, int featureCount) {
  Rng rng = Rng(seed).fork(1);  // not the stream of the route instance
  const RouteInstance instance = randomRouteInstance(seed, inspectorCount);
  MeetingProblem problem;
  problem.explorer = instance.explorer;
  problem.inspectors = instance.inspectors;
  for (int f = 0; f < featureCount; ++f) {
    const Vec3 at(rng.uniform(-20, 20), rng.uniform(-20, 20), rng.uniform(0, 5));
    problem.features.push_back({1000 + f, at + Vec3(0, 0, 1), at});
  }
  problem.explorationFinished = true;
  return problem;
}

// On instances whose routes the GA solves exactly (1-2 samples per pose), the decision is the
// cheapest ordered subset by brute force.
TEST(MeetingDecision, IsTheCheapestOrderedSubset) {
  const MeetingOptions options;
  int met = 0;
  for (uint64_t seed = 1; seed <= 8; ++seed) {
    const RouteInstance instance = randomRouteInstance(seed, 3, 1, 2);
    MeetingProblem problem = teamProblem(seed, 3, 5);
    problem.explorer = instance.explorer;
    problem.inspectors = instance.inspectors;
    const MeetingDecision decision = decideMeetings(problem, instance.points, options);
    EXPECT_EQ(decision.candidates, 3 + 6 + 6);
    double best = kInf;
    std::vector<int> bestOrder;
    for (const std::vector<int>& order : std::vector<std::vector<int>>{{0},
                                                                       {1},
                                                                       {2},
                                                                       {0, 1},
                                                                       {0, 2},
                                                                       {1, 0},
                                                                       {1, 2},
                                                                       {2, 0},
                                                                       {2, 1},
                                                                       {0, 1, 2},
                                                                       {0, 2, 1},
                                                                       {1, 0, 2},
                                                                       {1, 2, 0},
                                                                       {2, 0, 1},
                                                                       {2, 1, 0}}) {
      const OracleRoute route = bruteForce(problem.explorer, problem.inspectors, instance.points,
                                           order, options.inspectionTime, options.explorerLimits);
      if (std::isinf(route.cost)) continue;
      std::vector<double> times;
      oracleCost(problem.explorer, problem.inspectors, instance.points, order, route.picks,
                 options.inspectionTime, options.explorerLimits, &times);
      const double cost =
          route.cost + allocateFeatures(problem.inspectors, order, times, problem.features,
                                        problem.explorer.now, AllocationModel{})
                           .cost();
      if (cost < best) {
        best = cost;
        bestOrder = order;
      }
    }
    ASSERT_EQ(decision.choice, MeetingChoice::Meet) << seed;  // exploration is finished
    EXPECT_NEAR(decision.meetingCost, best, 1e-9) << seed;
    std::vector<int> order;
    for (const PlannedMeeting& meeting : decision.meetings) {
      order.push_back(meeting.inspector);
      EXPECT_FALSE(meeting.featureIds.empty());
    }
    EXPECT_EQ(order, bestOrder) << seed;
    if (order.size() > 1) ++met;
  }
  EXPECT_GT(met, 0);  // some decisions meet several inspectors, so the order matters
}

TEST(MeetingDecision, HandsOutEveryFeatureOnce) {
  const MeetingProblem problem = teamProblem(3, 4, 30);
  const MeetingDecision decision = decideMeetings(problem, bigBox(), openSpace(), {});
  ASSERT_EQ(decision.choice, MeetingChoice::Meet);
  EXPECT_EQ(decision.candidates, 4 + 12 + 24 + 24);
  std::vector<int64_t> ids;
  for (const PlannedMeeting& meeting : decision.meetings) {
    ids.insert(ids.end(), meeting.featureIds.begin(), meeting.featureIds.end());
    EXPECT_LE(meeting.arrival, meeting.meetingTime);
    const HoverWindow& pose = problem.inspectors[meeting.inspector].poses[meeting.pose];
    EXPECT_LE(meeting.arrival, pose.end);
    EXPECT_LE((meeting.point - pose.position).norm(), 4.0 + 1e-9);
  }
  std::sort(ids.begin(), ids.end());
  std::vector<int64_t> expected;
  for (const PendingFeature& feature : problem.features)
    expected.push_back(feature.id);
  EXPECT_EQ(ids, expected);
}

TEST(MeetingDecision, IsReproducibleBySeed) {
  const MeetingProblem problem = teamProblem(8, 4, 12);
  MeetingOptions options;
  options.seed = 42;
  const MeetingDecision a = decideMeetings(problem, bigBox(), openSpace(), options);
  const MeetingDecision b = decideMeetings(problem, bigBox(), openSpace(), options);
  ASSERT_EQ(a.choice, MeetingChoice::Meet);
  EXPECT_EQ(a.meetingCost, b.meetingCost);
  ASSERT_EQ(a.meetings.size(), b.meetings.size());
  for (size_t k = 0; k < a.meetings.size(); ++k) {
    EXPECT_EQ(a.meetings[k].inspector, b.meetings[k].inspector);
    EXPECT_EQ(a.meetings[k].point, b.meetings[k].point);
    EXPECT_EQ(a.meetings[k].arrival, b.meetings[k].arrival);
    EXPECT_EQ(a.meetings[k].featureIds, b.meetings[k].featureIds);
  }
}

TEST(MeetingDecision, LimitsTheSubsetsItTries) {
  MeetingOptions options;
  EXPECT_EQ(meetingSubsetLimit(4, 30, options), 4);
  EXPECT_EQ(meetingSubsetLimit(5, 30, options), 5);
  EXPECT_EQ(meetingSubsetLimit(6, 30, options), 3);
  EXPECT_EQ(meetingSubsetLimit(4, 2, options), 2);  // no meeting without a feature
  EXPECT_EQ(meetingSubsetLimit(4, 0, options), 0);
  options.maxInspectorsMet = 1;
  EXPECT_EQ(meetingSubsetLimit(4, 30, options), 1);

  const MeetingProblem six = teamProblem(5, 6, 8);
  const MeetingDecision decision = decideMeetings(six, bigBox(), openSpace(), MeetingOptions{});
  EXPECT_EQ(decision.candidates, 6 + 30 + 120);
  EXPECT_LE(decision.meetings.size(), 3u);

  options.maxInspectorsMet = -1;
  EXPECT_MENTIONS(testing::messageOf([&] { validateMeetingOptions(options); }), "maxInspectorsMet");
  options.maxInspectorsMet = 0;
  options.ga.mutationRate = 2.0;
  EXPECT_MENTIONS(testing::messageOf([&] { validateMeetingOptions(options); }), "mutationRate");
}

}  // namespace
}  // namespace coinspect::planning
