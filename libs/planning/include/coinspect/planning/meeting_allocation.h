// Handing pending features to the inspectors an explorer meets (SLEI3D's "MVRP"): greedy
// round-robin nearest neighbour, and the idle-time cost SOEI compares decisions with.
//
// Each met inspector ("agent") starts from its last planned pose at
//   start = max(meeting time, last window start + t_q)
// (it finishes its current plan first, and cannot take features before the explorer met it).
// The agents take turns in the meeting order; each takes the unassigned feature whose inspection
// pose is nearest (3-D, ties to the lower index) to where it is, and its finish time grows by the
// travel time plus t_q, until every feature is taken. High-priority features go first (SLEI3D's
// precedence in allocation): while one is left, a turn takes the nearest high-priority one.
// With R = the latest finish time (the "right axis"),
//   agent cost  = sum over agents of (its travel time + R - its finish)
//   others cost = sum over inspectors not met of max(0, R - max(now, last window start + t_q))
// i.e. the time the team spends not inspecting until the last feature is done. The reference
// charges unmet inspectors from their last window start + t_q even when that is before now;
// idle time already past cannot be saved by any decision, so it is counted from now here.
#pragma once

#include <cstdint>
#include <vector>

#include "coinspect/planning/meeting_route.h"

namespace coinspect::planning {

struct PendingFeature {
  int64_t id = 0;
  Vec3 position = Vec3::Zero();     // the feature itself
  Vec3 inspectFrom = Vec3::Zero();  // the hover position an inspector inspects it from
  bool highPriority = false;        // taken before every other feature
};

struct AllocationModel {
  double inspectionTime = 3.0;  // s, t_q
  TravelLimits inspector;       // the inspectors' trapezoid profile
};

struct InspectorAssignment {
  int inspector = 0;          // index into the inspectors vector
  double startTime = 0.0;     // s
  double finishTime = 0.0;    // s, after its last assigned feature
  double travelTime = 0.0;    // s, summed over its legs
  std::vector<int> features;  // indices into the features vector, in visiting order
};

struct FeatureAllocation {
  std::vector<InspectorAssignment> agents;  // in the order of `met`
  double rightAxis = 0.0;                   // s, R
  double agentCost = 0.0;
  double othersCost = 0.0;
  double cost() const { return agentCost + othersCost; }
};

// Allocates every feature to inspectors[met[a]], met at meetingTimes[a]. Throws InputError for an
// empty or invalid `met`, mismatched sizes, an inspector without poses, or a bad model.
FeatureAllocation allocateFeatures(const std::vector<InspectorPlan>& inspectors,
                                   const std::vector<int>& met,
                                   const std::vector<double>& meetingTimes,
                                   const std::vector<PendingFeature>& features, double now,
                                   const AllocationModel& model);

// When an inspector runs out of planned work: its last window start + t_q, or now if later.
double idleFrom(const InspectorPlan& inspector, double now, double inspectionTime);

}  // namespace coinspect::planning
