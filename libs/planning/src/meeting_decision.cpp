// SOEI: subsets x orders x (OptMeet + MVRP), against not meeting (see meeting_decision.h).
#include "coinspect/planning/meeting_decision.h"

#include <algorithm>
#include <limits>
#include <numeric>
#include <string>

#include "coinspect/core/error.h"
#include "coinspect/core/random.h"
#include "meeting_internal.h"

namespace coinspect::planning {

namespace {

// The reference's full enumeration stays affordable up to this many inspectors (325 orders);
// beyond, subsets of at most kAutomaticSubsetLimit inspectors (820 orders for 10).
constexpr int kFullEnumerationInspectors = 5;
constexpr int kAutomaticSubsetLimit = 3;

struct Candidate {
  std::vector<int> order;
  MeetingRoute route;
  FeatureAllocation allocation;
  double cost = std::numeric_limits<double>::infinity();
};

// Calls visit(order) for every ordered tuple of distinct indices in [0, n) of length `length`,
// in lexicographic order.
template <class Visit>
void forEachOrder(int n, int length, std::vector<int>& order, std::vector<bool>& used,
                  Visit& visit) {
  if (static_cast<int>(order.size()) == length) {
    visit(order);
    return;
  }
  for (int i = 0; i < n; ++i) {
    if (used[i]) continue;
    used[i] = true;
    order.push_back(i);
    forEachOrder(n, length, order, used, visit);
    order.pop_back();
    used[i] = false;
  }
}

MeetingDecision plannedDecision(const MeetingProblem& problem, const Candidate& best) {
  MeetingDecision decision;
  decision.choice = MeetingChoice::Meet;
  for (size_t k = 0; k < best.order.size(); ++k) {
    const MeetingStop& stop = best.route.stops[k];
    const InspectorAssignment& agent = best.allocation.agents[k];
    PlannedMeeting meeting;
    meeting.inspector = stop.inspector;
    meeting.inspectorId = problem.inspectors[stop.inspector].id;
    meeting.pose = stop.pick.pose;
    meeting.point = stop.point;
    meeting.arrival = stop.arrival;
    meeting.meetingTime = stop.meetingTime;
    for (const int feature : agent.features)
      meeting.featureIds.push_back(problem.features[feature].id);
    meeting.inspectorStart = agent.startTime;
    meeting.inspectorFinish = agent.finishTime;
    decision.meetings.push_back(std::move(meeting));
  }
  return decision;
}

}  // namespace

void validateMeetingOptions(const MeetingOptions& options) {
  validateMeetingSampling(options.sampling);
  MeetingRouteOptions route{options.inspectionTime, options.explorerLimits, options.ga};
  validateMeetingRoute(route);
  if (!(options.inspectorLimits.speed > 0.0 && options.inspectorLimits.acceleration > 0.0)) {
    throw InputError("meeting options", "inspectorLimits",
                     "speed and acceleration must be positive");
  }
  if (options.maxInspectorsMet < 0) {
    throw InputError("meeting options", "maxInspectorsMet",
                     std::to_string(options.maxInspectorsMet) + " is negative");
  }
}

int meetingSubsetLimit(int inspectors, int features, const MeetingOptions& options) {
  int limit = options.maxInspectorsMet;
  if (limit == 0)
    limit = inspectors <= kFullEnumerationInspectors ? inspectors : kAutomaticSubsetLimit;
  return std::max(0, std::min({limit, inspectors, features}));
}

std::vector<InspectorMeetingPoints> sampleInspectorMeetingPoints(
    const std::vector<InspectorPlan>& inspectors, double now, const MeetingBox& box,
    const MeetingSpace& space, const MeetingSamplingOptions& options) {
  std::vector<InspectorMeetingPoints> points;
  for (const InspectorPlan& inspector : inspectors) {
    InspectorMeetingPoints perPose;
    for (const HoverWindow& window : inspector.poses) {
      if (window.end < now) {
        perPose.emplace_back();  // nobody will be there any more
        continue;
      }
      perPose.push_back(sampleMeetingPoints(window.position, box, space, options));
    }
    points.push_back(std::move(perPose));
  }
  return points;
}

MeetingDecision decideMeetings(const MeetingProblem& problem,
                               const std::vector<InspectorMeetingPoints>& points,
                               const MeetingOptions& options) {
  validateMeetingOptions(options);
  const int n = static_cast<int>(problem.inspectors.size());
  if (static_cast<int>(points.size()) != n) {
    throw InputError(
        "meeting decision", "points",
        std::to_string(points.size()) + " point sets for " + std::to_string(n) + " inspectors");
  }
  const int limit = meetingSubsetLimit(n, static_cast<int>(problem.features.size()), options);
  MeetingDecision decision;
  if (limit == 0) return decision;  // nothing to hand over, or nobody to hand it to

  const MeetingRouteOptions routeOptions{options.inspectionTime, options.explorerLimits,
                                         options.ga};
  const AllocationModel allocationModel{options.inspectionTime, options.inspectorLimits};
  std::vector<detail::MeetingGenePool> pools;  // per inspector, shared by all orders
  std::vector<int> everyone(n);
  std::iota(everyone.begin(), everyone.end(), 0);
  detail::validateMeetingInputs(problem.inspectors, points, everyone);
  for (int i = 0; i < n; ++i) {
    pools.push_back(detail::meetingGenePool(problem.inspectors[i], points[i], problem.explorer.now,
                                            options.inspectionTime));
  }
  const Rng seeds(options.seed);
  Candidate best;
  int candidates = 0, feasible = 0;
  auto evaluate = [&](const std::vector<int>& order) {
    const uint64_t seed = seeds.fork(static_cast<uint64_t>(candidates)).next();
    ++candidates;
    Candidate candidate;
    candidate.order = order;
    std::vector<const detail::MeetingGenePool*> orderPools;
    for (const int index : order)
      orderPools.push_back(&pools[index]);
    candidate.route = detail::optimiseOnPools(problem.explorer, problem.inspectors, points, order,
                                              orderPools, routeOptions, seed);
    if (!candidate.route.feasible()) return;
    ++feasible;
    std::vector<double> meetingTimes;
    for (const MeetingStop& stop : candidate.route.stops)
      meetingTimes.push_back(stop.meetingTime);
    candidate.allocation =
        allocateFeatures(problem.inspectors, order, meetingTimes, problem.features,
                         problem.explorer.now, allocationModel);
    candidate.cost = candidate.route.cost + candidate.allocation.cost();
    if (candidate.cost < best.cost) best = std::move(candidate);
  };
  for (int length = 1; length <= limit; ++length) {
    std::vector<int> order;
    std::vector<bool> used(n, false);
    forEachOrder(n, length, order, used, evaluate);
  }

  if (feasible == 0) {
    decision.choice = MeetingChoice::NoFeasibleMeeting;
    decision.candidates = candidates;
    return decision;
  }
  const double rightAxis = best.allocation.rightAxis;
  double noMeetingCost = 0.0;
  for (const InspectorPlan& inspector : problem.inspectors) {
    const double idle = idleFrom(inspector, problem.explorer.now, options.inspectionTime);
    noMeetingCost += std::max(0.0, rightAxis - idle);
  }
  if (!problem.explorationFinished && noMeetingCost < best.cost) {
    decision.choice = MeetingChoice::NoMeeting;
  } else {
    decision = plannedDecision(problem, best);
  }
  decision.meetingCost = best.cost;
  decision.noMeetingCost = noMeetingCost;
  decision.rightAxis = rightAxis;
  decision.candidates = candidates;
  decision.feasibleCandidates = feasible;
  return decision;
}

MeetingDecision decideMeetings(const MeetingProblem& problem, const MeetingBox& box,
                               const MeetingSpace& space, const MeetingOptions& options) {
  validateMeetingOptions(options);
  // Sampling is the costly part: skip it when there is nothing to decide.
  const int limit = meetingSubsetLimit(static_cast<int>(problem.inspectors.size()),
                                       static_cast<int>(problem.features.size()), options);
  if (limit == 0) {
    return decideMeetings(problem, std::vector<InspectorMeetingPoints>(problem.inspectors.size()),
                          options);
  }
  const std::vector<InspectorMeetingPoints> points = sampleInspectorMeetingPoints(
      problem.inspectors, problem.explorer.now, box, space, options.sampling);
  return decideMeetings(problem, points, options);
}

}  // namespace coinspect::planning
