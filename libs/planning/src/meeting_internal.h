// Shared by meeting_route.cpp and meeting_decision.cpp: the flattened candidates of an
// inspector, built once per decision and reused by the GA of every order.
#pragma once

#include <algorithm>
#include <cstdint>
#include <limits>
#include <vector>

#include "coinspect/planning/meeting_route.h"

namespace coinspect::planning::detail {

// A meeting candidate with what the route's timeline needs of its pose's window.
struct MeetingCandidate {
  Vec3 point = Vec3::Zero();
  double start = 0.0;  // window start, s
  double end = 0.0;    // window end, s (+infinity for the last pose)
  // Open window: max(now, start + t_q), since when the inspector idles; closed: +infinity, so
  // that max(0, arrival - idleSince) is 0.
  double idleSince = 0.0;
  MeetingPick pick;
};

// What all candidates of one pose share, to bound their costs at once.
struct MeetingPoseSummary {
  Vec3 centre = Vec3::Zero();  // the hover position
  double radius = 0.0;         // m, the largest distance of a candidate from the centre
  MeetingCandidate window;     // its start, end and idleSince (point and pick unused)
};

// A gene is an index into `candidates`; those of pose p are [poseBegin[p], poseBegin[p + 1]).
struct MeetingGenePool {
  std::vector<MeetingCandidate> candidates;
  std::vector<size_t> poseBegin;
  std::vector<MeetingPoseSummary> poses;
  size_t poseCount() const { return poses.size(); }
};

// One leg of a route: fly from `from` (left at `departure`) to a candidate and meet there; the
// timeline of meeting_route.h. Inline: the GA's inner loops call it millions of times.
struct MeetingLeg {
  double travel = 0.0;
  double arrival = 0.0;
  double meetingTime = 0.0;
  double explorerWait = 0.0;
  double inspectorWait = 0.0;
  bool feasible = true;
  double cost() const { return travel + explorerWait + inspectorWait; }
};

inline MeetingLeg meetingLeg(const Vec3& from, double departure, const MeetingCandidate& to,
                             const TravelLimits& limits) {
  MeetingLeg leg;
  leg.travel = travelTime((to.point - from).norm(), limits);
  leg.arrival = departure + leg.travel;
  leg.feasible = leg.arrival <= to.end;
  leg.meetingTime = std::max(leg.arrival, to.start);
  leg.explorerWait = leg.meetingTime - leg.arrival;
  leg.inspectorWait = std::max(0.0, leg.arrival - to.idleSince);
  return leg;
}

MeetingCandidate meetingCandidate(const HoverWindow& window, const Vec3& point, MeetingPick pick,
                                  double now, double inspectionTime);

// Throws InputError for mismatched point sets, an index out of range or repeated in `order`, or
// an inspector of `order` without poses.
void validateMeetingInputs(const std::vector<InspectorPlan>& inspectors,
                           const std::vector<InspectorMeetingPoints>& points,
                           const std::vector<int>& order);

MeetingGenePool meetingGenePool(const InspectorPlan& inspector,
                                const InspectorMeetingPoints& points, double now,
                                double inspectionTime);

// optimiseMeetingRoute on prebuilt pools: pools[k] belongs to order[k]. Inputs are not validated.
MeetingRoute optimiseOnPools(const ExplorerState& explorer,
                             const std::vector<InspectorPlan>& inspectors,
                             const std::vector<InspectorMeetingPoints>& points,
                             const std::vector<int>& order,
                             const std::vector<const MeetingGenePool*>& pools,
                             const MeetingRouteOptions& options, uint64_t seed);

}  // namespace coinspect::planning::detail
