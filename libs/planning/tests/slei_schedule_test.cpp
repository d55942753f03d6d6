#include "coinspect/planning/slei_schedule.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <vector>

#include "coinspect/core/random.h"
#include "coinspect/planning/slei_meeting_order.h"
#include "coinspect/testing/input_errors.h"

namespace coinspect::planning {
namespace {

using testing::messageOf;

constexpr double kInf = std::numeric_limits<double>::infinity();

// ---------------------------------------------------------------------------------------------
// Task-completion prediction

CompletionInputs exploring(double boxVolume, double exploredVolume, int scanned, int inspected,
                           double timeInBox) {
  CompletionInputs inputs;
  inputs.boxVolume = boxVolume;
  inputs.exploredVolume = exploredVolume;
  inputs.featuresScanned = scanned;
  inputs.featuresInspected = inspected;
  inputs.timeInBox = timeInBox;
  return inputs;
}

CompletionInputs closing(double now, double earliestInspectorFinish, double tourLength) {
  CompletionInputs inputs = exploring(1000.0, 1000.0, 10, 10, 300.0);
  inputs.explorationFinished = true;
  inputs.now = now;
  inputs.earliestInspectorFinish = earliestInspectorFinish;
  inputs.closingTourLength = tourLength;
  return inputs;
}

TEST(SleiCompletion, NothingExploredGivesTheLowerClamp) {
  const CompletionPrediction p = predictCompletion(exploring(1000.0, 0.0, 0, 0, 30.0));
  EXPECT_EQ(p.rule, CompletionRule::NothingExplored);
  EXPECT_DOUBLE_EQ(p.remaining, 50.0);
}

TEST(SleiCompletion, NothingExploredTakesThePlannedSweepsTimeClamped) {
  auto inputs = exploring(1000.0, 0.0, 0, 0, 30.0);
  inputs.plannedSweepTime = 200.0;
  CompletionPrediction p = predictCompletion(inputs);
  EXPECT_EQ(p.rule, CompletionRule::NothingExplored);
  EXPECT_DOUBLE_EQ(p.remaining, 200.0);
  inputs.plannedSweepTime = 20.0;  // a sweep shorter than the floor: the floor
  EXPECT_DOUBLE_EQ(predictCompletion(inputs).remaining, 50.0);
  inputs.plannedSweepTime = 5000.0;
  p = predictCompletion(inputs);
  EXPECT_DOUBLE_EQ(p.unclamped, 5000.0);
  EXPECT_DOUBLE_EQ(p.remaining, 600.0);
  inputs.plannedSweepTime = -1.0;
  EXPECT_MENTIONS(messageOf([&] { predictCompletion(inputs); }), "plannedSweepTime");
  // Explored volume, however little, is extrapolated as before.
  inputs = exploring(1000.0, 250.0, 0, 0, 100.0);
  inputs.plannedSweepTime = 200.0;
  EXPECT_DOUBLE_EQ(predictCompletion(inputs).unclamped, 300.0);
}

TEST(SleiCompletion, WithoutFeaturesExtrapolatesTheVolume) {
  // A quarter explored in 100 s: three more quarters take 300 s.
  const CompletionPrediction p = predictCompletion(exploring(1000.0, 250.0, 0, 0, 100.0));
  EXPECT_EQ(p.rule, CompletionRule::VolumeExtrapolation);
  EXPECT_DOUBLE_EQ(p.unclamped, 300.0);
  EXPECT_DOUBLE_EQ(p.remaining, 300.0);
}

TEST(SleiCompletion, AllPredictedFeaturesScannedExtrapolatesTheVolume) {
  // N_pred = floor(10 * 1000 / 950) = 10 = N_s; T = 1000 / 950 * 3800 - 3800 = 200.
  const CompletionPrediction p = predictCompletion(exploring(1000.0, 950.0, 10, 0, 3800.0));
  EXPECT_EQ(p.rule, CompletionRule::VolumeExtrapolation);
  EXPECT_NEAR(p.remaining, 200.0, 1e-9);
}

TEST(SleiCompletion, FeaturesToFindButNoneInspectedGivesTheFallback) {
  // N_pred = floor(10 * 1000 / 500) = 20 > 10 scanned, nothing inspected yet.
  const CompletionPrediction p = predictCompletion(exploring(1000.0, 500.0, 10, 0, 60.0));
  EXPECT_EQ(p.rule, CompletionRule::UninspectedFallback);
  EXPECT_DOUBLE_EQ(p.remaining, 100.0);
}

TEST(SleiCompletion, FeaturesToFindExtrapolatesTheInspections) {
  // 5 of the 20 predicted features inspected in 60 s: 15 more take 180 s.
  const CompletionPrediction p = predictCompletion(exploring(1000.0, 500.0, 10, 5, 60.0));
  EXPECT_EQ(p.rule, CompletionRule::InspectionExtrapolation);
  EXPECT_DOUBLE_EQ(p.unclamped, 180.0);
  EXPECT_DOUBLE_EQ(p.remaining, 180.0);
}

TEST(SleiCompletion, FeaturesInspectedOnlyAfterTheBoxExtrapolateTheVolume) {
  // As in the fallback's case (20 predicted, 10 scanned, none inspected), but the features wait
  // for the box's end: half explored in 60 s, the other half takes 60 s.
  CompletionInputs in = exploring(1000.0, 500.0, 10, 0, 60.0);
  in.inspectedAfterExploration = true;
  const CompletionPrediction p = predictCompletion(in);
  EXPECT_EQ(p.rule, CompletionRule::VolumeExtrapolation);
  EXPECT_DOUBLE_EQ(p.remaining, 60.0);
}

TEST(SleiCompletion, PredictedCountOfAnExactRatioDoesNotRoundDown) {
  // (1 / 49) * 98 is 1.999... in doubles; 1 * 98 / 49 is exactly 2, so one feature is still to
  // find (the volume rule would give 98 / 49 * 60 - 60 = 60 s).
  const CompletionPrediction p = predictCompletion(exploring(98.0, 49.0, 1, 0, 60.0));
  EXPECT_EQ(p.rule, CompletionRule::UninspectedFallback);
  EXPECT_DOUBLE_EQ(p.remaining, 100.0);
}

TEST(SleiCompletion, ClosingTourWaitsForTheFirstInspectorThenTravels) {
  // Free at 1030 s, then 100 m at 2.5 m/s: 30 + 40 s.
  const CompletionPrediction p = predictCompletion(closing(1000.0, 1030.0, 100.0));
  EXPECT_EQ(p.rule, CompletionRule::ClosingTour);
  EXPECT_DOUBLE_EQ(p.remaining, 70.0);
}

TEST(SleiCompletion, ClosingTourStartsNowWhenAnInspectorIsAlreadyFree) {
  const CompletionPrediction p = predictCompletion(closing(1000.0, 900.0, 100.0));
  EXPECT_EQ(p.rule, CompletionRule::ClosingTour);
  EXPECT_DOUBLE_EQ(p.unclamped, 40.0);
  EXPECT_DOUBLE_EQ(p.remaining, 50.0);  // lower clamp
}

TEST(SleiCompletion, ClampsToTheDefaultBounds) {
  // 1 m^3 of 1000 in 10 s: 9990 s left, sent as 600 s.
  const CompletionPrediction high = predictCompletion(exploring(1000.0, 1.0, 0, 0, 10.0));
  EXPECT_DOUBLE_EQ(high.unclamped, 9990.0);
  EXPECT_DOUBLE_EQ(high.remaining, 600.0);
  // More explored than the box holds (the map's margin): negative, raised to 50 s.
  const CompletionPrediction low = predictCompletion(exploring(1000.0, 1200.0, 0, 0, 120.0));
  EXPECT_LT(low.unclamped, 0.0);
  EXPECT_DOUBLE_EQ(low.remaining, 50.0);
}

TEST(SleiCompletion, ClampsFallbackAndSpeedAreParameters) {
  CompletionPredictionOptions options;
  options.minRemaining = 10.0;
  options.maxRemaining = 1000.0;
  options.uninspectedFallback = 77.0;
  options.explorerSpeed = 5.0;
  EXPECT_DOUBLE_EQ(predictCompletion(exploring(1000.0, 0.0, 0, 0, 5.0), options).remaining, 10.0);
  EXPECT_DOUBLE_EQ(predictCompletion(exploring(1000.0, 500.0, 10, 0, 5.0), options).remaining,
                   77.0);
  EXPECT_DOUBLE_EQ(predictCompletion(exploring(1000.0, 1.0, 0, 0, 10.0), options).remaining,
                   1000.0);
  EXPECT_DOUBLE_EQ(predictCompletion(closing(1000.0, 900.0, 100.0), options).remaining, 20.0);
}

TEST(SleiCompletion, RejectsBadInputs) {
  CompletionPredictionOptions swapped;
  swapped.minRemaining = 700.0;
  EXPECT_MENTIONS(messageOf([&] { predictCompletion(exploring(1, 1, 0, 0, 1), swapped); }),
                  "minRemaining");
  EXPECT_MENTIONS(messageOf([] { predictCompletion(exploring(-1, 1, 0, 0, 1)); }), "boxVolume");
  EXPECT_MENTIONS(messageOf([] { predictCompletion(exploring(1, 1, -2, 0, 1)); }),
                  "featuresScanned");
  CompletionPredictionOptions still;
  still.explorerSpeed = 0.0;
  EXPECT_MENTIONS(messageOf([&] { predictCompletion(closing(0, 0, 1), still); }), "explorerSpeed");
}

TEST(SleiCompletion, StraightTourLengthIsHorizontalByDefault) {
  const std::vector<Vec3> stops = {Vec3(3, 4, 0), Vec3(3, 4, 20), Vec3(3, 10, 20)};
  EXPECT_DOUBLE_EQ(straightTourLength(Vec3(0, 0, 10), stops), 5.0 + 0.0 + 6.0);
  EXPECT_DOUBLE_EQ(straightTourLength(Vec3(0, 0, 10), stops, false), std::sqrt(125.0) + 20.0 + 6.0);
  EXPECT_DOUBLE_EQ(straightTourLength(Vec3(1, 2, 3), {}), 0.0);
}

// ---------------------------------------------------------------------------------------------
// Meeting place

const Vec3 kBoxMin(0.0, 0.0, 2.0), kBoxMax(10.0, 20.0, 8.0);

TEST(SleiMeetingCorner, CornersAreInsetAtTheMeetingHeight) {
  const std::array<Vec3, 4> corners = meetingCorners(kBoxMin, kBoxMax);
  EXPECT_TRUE(corners[0].isApprox(Vec3(1, 1, 0.5)));
  EXPECT_TRUE(corners[1].isApprox(Vec3(9, 1, 0.5)));
  EXPECT_TRUE(corners[2].isApprox(Vec3(9, 19, 0.5)));
  EXPECT_TRUE(corners[3].isApprox(Vec3(1, 19, 0.5)));
  MeetingCornerOptions options;
  options.inset = 2.5;
  options.height = 1.0;
  EXPECT_TRUE(meetingCorners(kBoxMin, kBoxMax, options)[2].isApprox(Vec3(7.5, 17.5, 1.0)));
}

TEST(SleiMeetingCorner, NarrowBoxKeepsCornersOnItsMiddleLine) {
  const std::array<Vec3, 4> corners = meetingCorners(Vec3(4, 0, 0), Vec3(5.5, 20, 3));
  for (const Vec3& corner : corners)
    EXPECT_DOUBLE_EQ(corner.x(), 4.75);
  EXPECT_DOUBLE_EQ(corners[0].y(), 1.0);
  EXPECT_DOUBLE_EQ(corners[2].y(), 19.0);
  EXPECT_MENTIONS(messageOf([] { meetingCorners(Vec3(1, 0, 0), Vec3(0, 1, 1)); }), "box");
}

TEST(SleiMeetingCorner, NearestCornerIsChosenInXY) {
  EXPECT_EQ(nearestMeetingCorner(kBoxMin, kBoxMax, Vec3(100, -5, 50)).index, 1);
  // Far below corner 3 but right under it in XY.
  const MeetingCornerChoice below = nearestMeetingCorner(kBoxMin, kBoxMax, Vec3(1, 19, -300));
  EXPECT_EQ(below.index, 3);
  EXPECT_TRUE(below.point.isApprox(Vec3(1, 19, 0.5)));
  // From the centre all four are as near: the first one.
  EXPECT_EQ(nearestMeetingCorner(kBoxMin, kBoxMax, Vec3(5, 10, 0)).index, 0);
}

TEST(SleiMeetingCorner, TimedChoicePrefersTheArrivalThatMatchesThePlannedTime) {
  // GCS at the origin at t = 100 s, 1 m/s. Box corners (11,1), (29,1), (29,19), (11,19):
  // arrivals 111.0, 129.0, 134.7, 121.9 s.
  const Vec3 boxMin(10, 0, 0), boxMax(30, 20, 5);
  const auto arrival = [](const Vec3& corner) { return 100.0 + corner.head<2>().norm(); };
  EXPECT_EQ(nearestMeetingCorner(boxMin, boxMax, Vec3::Zero()).index, 0);
  const MeetingCornerChoice late = bestTimedMeetingCorner(boxMin, boxMax, arrival, 140.0);
  EXPECT_EQ(late.index, 2);
  EXPECT_NEAR(late.arrival, 100.0 + std::hypot(29.0, 19.0), 1e-9);
  EXPECT_EQ(bestTimedMeetingCorner(boxMin, boxMax, arrival, 125.0).index, 3);
  EXPECT_EQ(bestTimedMeetingCorner(boxMin, boxMax, arrival, 0.0).index, 0);
}

TEST(SleiMeetingCorner, TimedChoiceTiesGoToTheEarlierArrivalThenCornerOrder) {
  const std::array<Vec3, 4> corners = meetingCorners(kBoxMin, kBoxMax);
  const auto table = [&](std::array<double, 4> times) {
    return [corners, times](const Vec3& point) {
      for (int i = 0; i < 4; ++i) {
        if (corners[i].isApprox(point)) return times[i];
      }
      return kInf;
    };
  };
  EXPECT_EQ(bestTimedMeetingCorner(kBoxMin, kBoxMax, table({110, 90, 130, 140}), 100.0).index, 1);
  EXPECT_EQ(bestTimedMeetingCorner(kBoxMin, kBoxMax, table({140, 110, 110, 90}), 100.0).index, 3);
  EXPECT_EQ(bestTimedMeetingCorner(kBoxMin, kBoxMax, table({130, 95, 95, 95}), 100.0).index, 1);
}

TEST(SleiMeetingCorner, TimedChoiceSkipsUnreachableCorners) {
  const auto onlyLast = [](const Vec3& corner) {
    return corner.x() < 5 && corner.y() > 5 ? 500.0 : kInf;
  };
  const MeetingCornerChoice choice = bestTimedMeetingCorner(kBoxMin, kBoxMax, onlyLast, 100.0);
  EXPECT_EQ(choice.index, 3);
  EXPECT_DOUBLE_EQ(choice.arrival, 500.0);
  const auto nowhere = [](const Vec3&) { return kInf; };
  EXPECT_EQ(bestTimedMeetingCorner(kBoxMin, kBoxMax, nowhere, 100.0).index, -1);
}

// ---------------------------------------------------------------------------------------------
// GCS meeting order

GcsMeeting meeting(int id, double x, double y, double earliest, double latest,
                   double service = 0.0) {
  GcsMeeting m;
  m.id = id;
  m.place = Vec3(x, y, 0.5);
  m.earliest = earliest;
  m.latest = latest;
  m.service = service;
  return m;
}

// The oracle's own timeline (not the library's), ranked (max lateness, total, completion).
struct OracleRank {
  double maxLateness = 0.0, totalLateness = 0.0, completion = 0.0;
};

OracleRank oracleRank(const MeetingOrderProblem& problem, const std::vector<int>& order) {
  OracleRank rank;
  double clock = problem.startTime;
  Vec3 at = problem.start;
  for (const int index : order) {
    const GcsMeeting& m = problem.meetings[index];
    const double arrival = clock + problem.travelTime(at, m.place);
    const double lateness = std::max(0.0, arrival - m.latest);
    rank.maxLateness = std::max(rank.maxLateness, lateness);
    rank.totalLateness += lateness;
    clock = std::max(arrival, m.earliest) + m.service;
    at = m.place;
  }
  rank.completion = clock;
  return rank;
}

bool oracleBefore(const OracleRank& a, const OracleRank& b) {
  if (a.maxLateness != b.maxLateness) return a.maxLateness < b.maxLateness;
  if (a.totalLateness != b.totalLateness) return a.totalLateness < b.totalLateness;
  return a.completion < b.completion;
}

OracleRank bruteForce(const MeetingOrderProblem& problem) {
  std::vector<int> order(problem.meetings.size());
  std::iota(order.begin(), order.end(), 0);
  OracleRank best = oracleRank(problem, order);
  while (std::next_permutation(order.begin(), order.end())) {
    const OracleRank rank = oracleRank(problem, order);
    if (oracleBefore(rank, best)) best = rank;
  }
  return best;
}

// Random meetings in a 100 m square, windows from tight to open, some service time.
MeetingOrderProblem randomProblem(Rng& rng, int n) {
  MeetingOrderProblem problem;
  problem.start = Vec3(rng.uniform(-50, 50), rng.uniform(-50, 50), 0.0);
  problem.startTime = rng.uniform(0, 20);
  problem.travelTime = groundTravelTime(1.0);
  for (int i = 0; i < n; ++i) {
    const double earliest = rng.uniform(0, 200);
    const double width = rng.uniform() < 0.15 ? kInf : rng.uniform(5, 150);
    problem.meetings.push_back(meeting(100 + i, rng.uniform(-50, 50), rng.uniform(-50, 50),
                                       earliest, earliest + width, rng.uniform(0, 15)));
  }
  return problem;
}

void expectPermutation(const std::vector<int>& order, size_t n) {
  std::vector<int> sorted = order;
  std::sort(sorted.begin(), sorted.end());
  std::vector<int> expected(n);
  std::iota(expected.begin(), expected.end(), 0);
  EXPECT_EQ(sorted, expected);
}

TEST(SleiMeetingOrder, TimelineWaitsWhenEarlyAndCountsLateness) {
  MeetingOrderProblem problem;
  problem.start = Vec3(0, 0, 7);  // the height does not count on the ground
  problem.startTime = 10.0;
  problem.meetings = {meeting(7, 30, 40, 100, 200, 5), meeting(8, 30, 0, 0, 120, 2)};
  const MeetingSchedule schedule = evaluateMeetingOrder(problem, {0, 1});
  ASSERT_EQ(schedule.stops.size(), 2u);
  EXPECT_EQ(schedule.stops[0].id, 7);
  EXPECT_DOUBLE_EQ(schedule.stops[0].arrival, 60.0);  // 50 m at 1 m/s
  EXPECT_DOUBLE_EQ(schedule.stops[0].start, 100.0);   // waits for the window
  EXPECT_DOUBLE_EQ(schedule.stops[0].departure, 105.0);
  EXPECT_DOUBLE_EQ(schedule.stops[1].arrival, 145.0);  // 40 m
  EXPECT_DOUBLE_EQ(schedule.stops[1].lateness, 25.0);
  EXPECT_DOUBLE_EQ(schedule.completion, 147.0);
  EXPECT_FALSE(schedule.allWindowsMet);
  // The other way round meets both windows.
  const MeetingSchedule best = planMeetingOrder(problem);
  EXPECT_EQ(best.order, (std::vector<int>{1, 0}));
  EXPECT_TRUE(best.allWindowsMet);
  EXPECT_TRUE(best.exact);
  EXPECT_DOUBLE_EQ(best.completion, 105.0);  // 8 at 40-42 s, 7 reached at 82 s, wait to 100
}

TEST(SleiMeetingOrder, NoMeetingsIsAnEmptyScheduleAtTheStartTime) {
  MeetingOrderProblem problem;
  problem.startTime = 42.0;
  const MeetingSchedule schedule = planMeetingOrder(problem);
  EXPECT_TRUE(schedule.order.empty());
  EXPECT_TRUE(schedule.allWindowsMet);
  EXPECT_DOUBLE_EQ(schedule.completion, 42.0);
}

TEST(SleiMeetingOrder, ExactMatchesBruteForceOnRandomInstances) {
  Rng rng(20240611);
  int feasible = 0, infeasible = 0;
  for (int trial = 0; trial < 400; ++trial) {
    const int n = 1 + static_cast<int>(rng.below(7));
    MeetingOrderProblem problem = randomProblem(rng, n);
    if (trial % 4 == 3) {  // asymmetric travel: uphill one way
      problem.travelTime = [](const Vec3& a, const Vec3& b) {
        return (b - a).head<2>().norm() / 1.5 + std::max(0.0, b.x() - a.x()) * 0.4;
      };
    }
    const OracleRank oracle = bruteForce(problem);
    const MeetingSchedule schedule = planMeetingOrder(problem);
    SCOPED_TRACE("trial " + std::to_string(trial));
    ASSERT_TRUE(schedule.exact);
    expectPermutation(schedule.order, problem.meetings.size());
    EXPECT_NEAR(schedule.maxLateness, oracle.maxLateness, 1e-9);
    EXPECT_NEAR(schedule.totalLateness, oracle.totalLateness, 1e-9);
    EXPECT_NEAR(schedule.completion, oracle.completion, 1e-9);
    EXPECT_EQ(schedule.allWindowsMet, oracle.maxLateness == 0.0);
    // The reported timeline is the order's own.
    const OracleRank own = oracleRank(problem, schedule.order);
    EXPECT_NEAR(own.completion, schedule.completion, 1e-9);
    ++(oracle.maxLateness == 0.0 ? feasible : infeasible);
  }
  // The generator must exercise both the hard-window and the soft fallback programmes.
  EXPECT_GT(feasible, 50);
  EXPECT_GT(infeasible, 50);
}

// A planted order: meetings placed at random, windows around the times of visiting them in that
// order, so at least that order meets every window.
MeetingOrderProblem plantedProblem(Rng& rng, int n, double slack) {
  MeetingOrderProblem problem;
  problem.start = Vec3::Zero();
  problem.travelTime = groundTravelTime(1.0);
  Vec3 at = problem.start;
  double clock = 0.0;
  for (int i = 0; i < n; ++i) {
    const Vec3 place(rng.uniform(-60, 60), rng.uniform(-60, 60), 0.5);
    clock += (place - at).head<2>().norm();
    const double service = rng.uniform(0, 10);
    problem.meetings.push_back(
        meeting(i, place.x(), place.y(), clock - slack, clock + slack, service));
    clock += service;
    at = place;
  }
  // Shuffle so that the index order says nothing.
  for (int i = n - 1; i > 0; --i) {
    std::swap(problem.meetings[i], problem.meetings[rng.below(static_cast<uint64_t>(i) + 1)]);
  }
  return problem;
}

TEST(SleiMeetingOrder, HeuristicAgreesWithTheProgrammeOnEasyInstances) {
  Rng rng(77);
  for (int trial = 0; trial < 60; ++trial) {
    SCOPED_TRACE("trial " + std::to_string(trial));
    const int n = 3 + static_cast<int>(rng.below(8));
    MeetingOrderProblem problem = plantedProblem(rng, n, 15.0);
    const MeetingSchedule exact = exactMeetingOrder(problem);
    const MeetingSchedule heuristic = heuristicMeetingOrder(problem);
    EXPECT_TRUE(exact.allWindowsMet);
    EXPECT_EQ(heuristic.allWindowsMet, exact.allWindowsMet);
    EXPECT_FALSE(heuristic.exact);
    expectPermutation(heuristic.order, problem.meetings.size());
    EXPECT_FALSE(ranksBefore(heuristic, exact));  // never better than the optimum
    // One meeting that cannot be reached in time makes both infeasible.
    problem.meetings[0].place = Vec3(500, 0, 0.5);
    problem.meetings[0].earliest = 0.0;
    problem.meetings[0].latest = 100.0;
    EXPECT_FALSE(exactMeetingOrder(problem).allWindowsMet);
    EXPECT_FALSE(heuristicMeetingOrder(problem).allWindowsMet);
  }
}

TEST(SleiMeetingOrder, InfeasibleInstanceReturnsTheLeastLateOrder) {
  // A (10 m east) by 10 s, B (20 m west) by 20 s: A first leaves B 20 s late, B first leaves A
  // 40 s late.
  MeetingOrderProblem problem;
  problem.meetings = {meeting(1, -20, 0, 0, 20), meeting(2, 10, 0, 0, 10)};
  for (const MeetingSchedule& schedule :
       {planMeetingOrder(problem), heuristicMeetingOrder(problem)}) {
    EXPECT_FALSE(schedule.allWindowsMet);
    EXPECT_EQ(schedule.order, (std::vector<int>{1, 0}));
    EXPECT_DOUBLE_EQ(schedule.maxLateness, 20.0);
    EXPECT_DOUBLE_EQ(schedule.totalLateness, 20.0);
    EXPECT_DOUBLE_EQ(schedule.completion, 40.0);
  }
  // The largest lateness counts before the total: A (10 m away) by 0 s, B (5 m away, 10 m from
  // A) by 10 s. A first: late 10 s at A and 10 s at B (largest 10, total 20); B first: on time
  // at B, 15 s late at A (largest 15, total 15). The first order wins.
  MeetingOrderProblem tradeOff;
  tradeOff.meetings = {meeting(1, 10, 0, 0, 0), meeting(2, 1.25, std::sqrt(23.4375), 0, 10)};
  for (const MeetingSchedule& schedule :
       {planMeetingOrder(tradeOff), heuristicMeetingOrder(tradeOff)}) {
    EXPECT_EQ(schedule.order, (std::vector<int>{0, 1}));
    EXPECT_NEAR(schedule.maxLateness, 10.0, 1e-9);
    EXPECT_NEAR(schedule.totalLateness, 20.0, 1e-9);
  }
}

TEST(SleiMeetingOrder, SortingByPlannedTimeIsWorseThanTheProgramme) {
  // The reference serves meetings by planned (earliest) time: far A (planned 10 s) before near B
  // (planned 20 s) drives 100 m out and 99 m back, reaching B at 199 s, after its 150 s limit.
  MeetingOrderProblem problem;
  problem.meetings = {meeting(1, 100, 0, 10, 500), meeting(2, 1, 0, 20, 150)};
  std::vector<int> byTime = {0, 1};
  std::stable_sort(byTime.begin(), byTime.end(), [&](int a, int b) {
    return problem.meetings[a].earliest < problem.meetings[b].earliest;
  });
  const MeetingSchedule sorted = evaluateMeetingOrder(problem, byTime);
  const MeetingSchedule best = planMeetingOrder(problem);
  EXPECT_FALSE(sorted.allWindowsMet);
  EXPECT_DOUBLE_EQ(sorted.completion, 199.0);
  EXPECT_TRUE(best.allWindowsMet);
  EXPECT_EQ(best.order, (std::vector<int>{1, 0}));
  EXPECT_DOUBLE_EQ(best.completion, 119.0);  // B at 1 s, wait to 20 s, 99 m to A
  EXPECT_TRUE(ranksBefore(best, sorted));
  // Even with every window open, sorting by time costs 80 s more.
  problem.meetings[1].latest = kInf;
  EXPECT_DOUBLE_EQ(evaluateMeetingOrder(problem, byTime).completion, 199.0);
  EXPECT_DOUBLE_EQ(planMeetingOrder(problem).completion, 119.0);
}

TEST(SleiMeetingOrder, LargeInstancesUseTheHeuristic) {
  Rng rng(5);
  const MeetingOrderProblem problem = plantedProblem(rng, 30, 20.0);
  const MeetingSchedule schedule = planMeetingOrder(problem);
  EXPECT_FALSE(schedule.exact);
  EXPECT_TRUE(schedule.allWindowsMet);
  expectPermutation(schedule.order, problem.meetings.size());
  MeetingOrderOptions heuristicOnly;
  heuristicOnly.exactLimit = 0;
  Rng small(6);
  EXPECT_FALSE(planMeetingOrder(plantedProblem(small, 5, 20.0), heuristicOnly).exact);
}

TEST(SleiMeetingOrder, RejectsBadProblems) {
  MeetingOrderProblem problem;
  problem.meetings = {meeting(1, 0, 0, 50, 40)};
  EXPECT_MENTIONS(messageOf([&] { planMeetingOrder(problem); }), "meeting 0");
  problem.meetings = {meeting(1, 0, 0, 0, 40), meeting(2, 5, 0, 0, 40)};
  problem.travelTime = [](const Vec3&, const Vec3&) { return -1.0; };
  EXPECT_MENTIONS(messageOf([&] { planMeetingOrder(problem); }), "travelTime");
  problem.travelTime = nullptr;
  EXPECT_MENTIONS(messageOf([&] { evaluateMeetingOrder(problem, {1, 1}); }), "order");
  EXPECT_MENTIONS(messageOf([&] { evaluateMeetingOrder(problem, {1}); }), "order");
  MeetingOrderOptions tooMany;
  tooMany.exactLimit = 17;
  EXPECT_MENTIONS(messageOf([&] { planMeetingOrder(problem, tooMany); }), "exactLimit");
  problem.meetings.assign(17, meeting(1, 0, 0, 0, kInf));
  EXPECT_MENTIONS(messageOf([&] { exactMeetingOrder(problem); }), "exact limit");
}

// FF3E's bound: nearest first, each stop only if the meeting is still reached from it in time.
TEST(DeadlineBoundedTour, KeepsOnlyStopsFromWhichTheMeetingIsReachedInTime) {
  const Vec3 origin = Vec3::Zero();
  const std::vector<Vec3> stops{Vec3(1, 0, 0), Vec3(10, 0, 0), Vec3(2, 0, 0)};
  const double unbounded = std::numeric_limits<double>::infinity();
  EXPECT_EQ(deadlineBoundedTour(origin, 0.0, stops, origin, unbounded, 1.0),
            (std::vector<size_t>{0, 2, 1}));
  // By 10 s: (1, 0, 0) at 1 s, back by 2; (2, 0, 0) at 2 s, back by 4; (10, 0, 0) at 10 s,
  // back by 20: dropped.
  EXPECT_EQ(deadlineBoundedTour(origin, 0.0, stops, origin, 10.0, 1.0),
            (std::vector<size_t>{0, 2}));
  // The same at half the speed with a travel factor of 2 is four times as long: none by 7 s
  // (the nearest is back by 8), the first by 8.
  EXPECT_TRUE(deadlineBoundedTour(origin, 0.0, stops, origin, 7.0, 0.5, 2.0).empty());
  EXPECT_EQ(deadlineBoundedTour(origin, 0.0, stops, origin, 8.0, 0.5, 2.0),
            (std::vector<size_t>{0}));
  // A nearer stop away from the meeting is skipped for one on the way.
  const std::vector<Vec3> sides{Vec3(2.5, 0, 0), Vec3(-3, 0, 0)};
  EXPECT_EQ(deadlineBoundedTour(origin, 100.0, sides, Vec3(-4, 0, 0), 108.0, 1.0),
            (std::vector<size_t>{1}));
}

TEST(SleiFrontierSearch, TheBestGainPerSecondWithinTheDeadlineThenNearestFirst) {
  const Vec3 origin = Vec3::Zero();
  const double unbounded = std::numeric_limits<double>::infinity();
  // Little on the way to much: one step ahead (depth 1) takes the big one first and comes back;
  // two steps ahead take the small one on the way (21 in 2 s beats 20 in 2 s).
  const std::vector<Vec3> line{Vec3(1, 0, 0), Vec3(2, 0, 0)};
  const std::vector<double> gains{1.0, 20.0};
  FrontierSearchOptions options;
  options.depth = 1;
  EXPECT_EQ(deadlineBoundedSearch(origin, 0.0, line, gains, origin, unbounded, 1.0, options),
            (std::vector<size_t>{1, 0}));
  options.depth = 2;
  EXPECT_EQ(deadlineBoundedSearch(origin, 0.0, line, gains, origin, unbounded, 1.0, options),
            (std::vector<size_t>{0, 1}));
  // Ten seconds at each stop: the big one alone (20 in 12 s) beats both (21 in 22 s).
  options.dwell = 10.0;
  EXPECT_EQ(deadlineBoundedSearch(origin, 0.0, line, gains, origin, unbounded, 1.0, options),
            (std::vector<size_t>{1, 0}));
  // Back at the start by 3 s: the far one does not fit (2 s there, 2 back), the near one does.
  options.dwell = 0.0;
  EXPECT_EQ(deadlineBoundedSearch(origin, 100.0, line, gains, origin, 103.0, 1.0, options),
            (std::vector<size_t>{0}));
  EXPECT_TRUE(
      deadlineBoundedSearch(origin, 100.0, line, gains, origin, 101.0, 1.0, options).empty());
  // After the best sequence, the rest nearest first: the big one on the other side, then the
  // small ones from there.
  const std::vector<Vec3> sides{Vec3(1, 0, 0), Vec3(-2, 0, 0), Vec3(3, 0, 0)};
  options.depth = 1;
  EXPECT_EQ(
      deadlineBoundedSearch(origin, 0.0, sides, {1.0, 10.0, 1.0}, origin, unbounded, 1.0, options),
      (std::vector<size_t>{1, 0, 2}));
  // Depth 0 is the greedy tour.
  options.depth = 0;
  EXPECT_EQ(
      deadlineBoundedSearch(origin, 0.0, sides, {1.0, 10.0, 1.0}, origin, unbounded, 1.0, options),
      deadlineBoundedTour(origin, 0.0, sides, origin, unbounded, 1.0));
  EXPECT_THROW(deadlineBoundedSearch(origin, 0.0, sides, {1.0}, origin, 10.0, 1.0, options),
               InputError);
  EXPECT_THROW(
      deadlineBoundedSearch(origin, 0.0, sides, {1.0, -1.0, 1.0}, origin, 10.0, 1.0, options),
      InputError);
}

}  // namespace
}  // namespace coinspect::planning
