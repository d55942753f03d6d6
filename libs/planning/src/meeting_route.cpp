// OptMeet: the meeting route's timeline and candidates (see meeting_route.h); the genetic
// algorithm is in meeting_genetic.cpp.
#include "coinspect/planning/meeting_route.h"

#include <algorithm>
#include <limits>
#include <string>

#include "coinspect/core/error.h"
#include "meeting_internal.h"

namespace coinspect::planning {

namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

}  // namespace

namespace detail {

MeetingCandidate meetingCandidate(const HoverWindow& window, const Vec3& point, MeetingPick pick,
                                  double now, double inspectionTime) {
  MeetingCandidate candidate;
  candidate.point = point;
  candidate.start = window.start;
  candidate.end = window.end;
  // Idle at its last pose since start + t_q; time before `now` is already lost either way.
  candidate.idleSince =
      window.end == kOpenWindowEnd ? std::max(now, window.start + inspectionTime) : kInfinity;
  candidate.pick = pick;
  return candidate;
}

void validateMeetingInputs(const std::vector<InspectorPlan>& inspectors,
                           const std::vector<InspectorMeetingPoints>& points,
                           const std::vector<int>& order) {
  const char* const source = "meeting route";
  if (points.size() != inspectors.size()) {
    throw InputError(source, "points",
                     std::to_string(points.size()) + " point sets for " +
                         std::to_string(inspectors.size()) + " inspectors");
  }
  std::vector<bool> seen(inspectors.size(), false);
  for (const int index : order) {
    if (index < 0 || index >= static_cast<int>(inspectors.size()) || seen[index]) {
      throw InputError(source, "order",
                       "inspector " + std::to_string(index) + " is out of range or repeated");
    }
    seen[index] = true;
    if (inspectors[index].poses.empty()) {
      throw InputError(source, "inspector " + std::to_string(index), "has no planned pose");
    }
    if (points[index].size() != inspectors[index].poses.size()) {
      throw InputError(source, "inspector " + std::to_string(index),
                       std::to_string(points[index].size()) + " point sets for " +
                           std::to_string(inspectors[index].poses.size()) + " poses");
    }
  }
}

MeetingGenePool meetingGenePool(const InspectorPlan& inspector,
                                const InspectorMeetingPoints& points, double now,
                                double inspectionTime) {
  MeetingGenePool pool;
  for (size_t pose = 0; pose < points.size(); ++pose) {
    const HoverWindow& window = inspector.poses[pose];
    MeetingPoseSummary summary;
    summary.centre = window.position;
    summary.window = meetingCandidate(window, window.position, {}, now, inspectionTime);
    pool.poseBegin.push_back(pool.candidates.size());
    for (size_t sample = 0; sample < points[pose].size(); ++sample) {
      const MeetingPick pick{static_cast<int>(pose), static_cast<int>(sample)};
      pool.candidates.push_back(
          meetingCandidate(window, points[pose][sample], pick, now, inspectionTime));
      summary.radius = std::max(summary.radius, (points[pose][sample] - window.position).norm());
    }
    pool.poses.push_back(summary);
  }
  pool.poseBegin.push_back(pool.candidates.size());
  return pool;
}

}  // namespace detail

void validateMeetingRoute(const MeetingRouteOptions& options) {
  const char* const source = "meeting route options";
  const MeetingGaOptions& ga = options.ga;
  if (ga.population < 1)
    throw InputError(source, "population", std::to_string(ga.population) + " is below 1");
  if (ga.generations < 0)
    throw InputError(source, "generations", std::to_string(ga.generations) + " is negative");
  if (!(ga.mutationRate >= 0.0 && ga.mutationRate <= 1.0)) {
    throw InputError(source, "mutationRate", std::to_string(ga.mutationRate) + " is not in [0, 1]");
  }
  if (ga.elites < 0) throw InputError(source, "elites", std::to_string(ga.elites) + " is negative");
  if (ga.polishSweeps < 0) {
    throw InputError(source, "polishSweeps", std::to_string(ga.polishSweeps) + " is negative");
  }
  if (!(options.inspectionTime >= 0.0)) {
    throw InputError(source, "inspectionTime",
                     std::to_string(options.inspectionTime) + " is negative");
  }
  if (!(options.explorer.speed > 0.0 && options.explorer.acceleration > 0.0))
    throw InputError(source, "explorer", "speed and acceleration must be positive");
}

MeetingRoute evaluateMeetingRoute(const ExplorerState& explorer,
                                  const std::vector<InspectorPlan>& inspectors,
                                  const std::vector<InspectorMeetingPoints>& points,
                                  const std::vector<int>& order,
                                  const std::vector<MeetingPick>& picks,
                                  const MeetingRouteOptions& options) {
  detail::validateMeetingInputs(inspectors, points, order);
  if (picks.size() != order.size()) {
    throw InputError("meeting route", "picks",
                     std::to_string(picks.size()) + " picks for " + std::to_string(order.size()) +
                         " inspectors");
  }
  MeetingRoute route;
  route.cost = 0.0;
  Vec3 position = explorer.position;
  double clock = explorer.now;
  for (size_t k = 0; k < order.size(); ++k) {
    const MeetingPick& pick = picks[k];
    const InspectorMeetingPoints& candidates = points[order[k]];
    if (pick.pose < 0 || pick.pose >= static_cast<int>(candidates.size()) || pick.sample < 0 ||
        pick.sample >= static_cast<int>(candidates[pick.pose].size())) {
      throw InputError("meeting route", "pick " + std::to_string(k), "no such candidate");
    }
    MeetingStop stop;
    stop.inspector = order[k];
    stop.pick = pick;
    stop.point = candidates[pick.pose][pick.sample];
    const detail::MeetingLeg leg = detail::meetingLeg(
        position, clock,
        detail::meetingCandidate(inspectors[order[k]].poses[pick.pose], stop.point, pick,
                                 explorer.now, options.inspectionTime),
        options.explorer);
    stop.arrival = leg.arrival;
    stop.meetingTime = leg.meetingTime;
    stop.explorerWait = leg.explorerWait;
    stop.inspectorWait = leg.inspectorWait;
    stop.feasible = leg.feasible;
    route.cost += leg.cost();
    if (!leg.feasible) route.cost = kInfinity;
    route.stops.push_back(stop);
    position = stop.point;
    clock = leg.meetingTime;
  }
  return route;
}

}  // namespace coinspect::planning
