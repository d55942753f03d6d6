// SLEI3D's SOEI decision: which of its inspectors an explorer meets, in which order, where, and
// which pending features it hands each of them - or whether it should not meet anyone yet.
//
//   1. SampleLOS (meeting_sampling.h): candidate meeting points around every hover pose of every
//      inspector, once per decision.
//   2. For every non-empty subset of the inspectors, in every order (a "candidate"):
//      OptMeet (meeting_route.h) picks the meeting points, MVRP (meeting_allocation.h) hands all
//      pending features to the inspectors met; candidate cost = route cost + allocation cost.
//   3. The cheapest candidate (R_best = its right axis) is compared with not meeting, whose cost
//      is sum over all inspectors of max(0, R_best - max(now, last window start + t_q)); not
//      meeting is allowed only while exploration is unfinished.
//
// Deviations from the reference code (TRIO-PKU/SLEI3D, exp_meeting_manager.py and
// decision_making/*), each because the reference is slower, inconsistent or unsafe there:
//   - Travel time is the exact rest-to-rest trapezoid/triangle (travel_time.h), for the explorer
//     and the inspectors; the reference uses sqrt(2 d / a) on short legs.
//   - The route's clock waits for the inspector (next departure = max(arrival, window start));
//     the reference adds travel only, as if the explorer could leave before the meeting.
//   - The GA minimises the cost itself; the reference maximises 1 / cost (0.01 for a zero cost).
//     A mutated gene is uniform over all the inspector's candidates. Its answer is polished by
//     coordinate descent (meeting_route.h; MeetingGaOptions::polishSweeps = 0 turns it off): on
//     small instances the GA alone misses the brute-force optimum in about a third of the runs,
//     the polished one in about 1 %.
//   - Line of sight on a VoxelGrid walks every cell the segment crosses and needs them known
//     free (the reference samples every 0.2 m and rejects occupied cells within 2 voxels; give
//     voxelGridMeetingSpace a sightClearance for such a margin).
//   - Sampling scans only the ball it keeps (same nodes as the reference's +-range cube), drops
//     nodes closer than minSeparation (1 m) to the pose so the explorer does not fly into the
//     hovering inspector, and skips poses whose window ended before now. A pose without samples
//     offers no meeting point (the reference would meet at the pose itself); an inspector with
//     no candidate at all cannot be met this time.
//   - Unmet inspectors are charged idle time from max(now, last window start + t_q), as in the
//     no-meeting cost; the reference starts at last window start + t_q even when it is past.
//   - At most min(number of features, maxInspectorsMet) inspectors are met: round robin gives
//     every agent a feature only then, so no meeting carries nothing (the reference plans such
//     meetings, then drops them when executing). maxInspectorsMet = 0 means all inspectors when
//     there are at most 5 of them (325 candidates), else 3 (820 candidates for 10 inspectors);
//     the reference enumerates every subset, which grows as n!.
//   - No pending feature: no meeting (the reference does not run the decision then).
//   - Candidates run one after another in a fixed order (subset size, then lexicographic order
//     of the inspector indices), each GA seeded from options.seed and the candidate's index; the
//     first of equal costs wins, and not meeting wins only when strictly cheaper. The reference
//     runs one process per candidate.
#pragma once

#include <cstdint>
#include <limits>
#include <vector>

#include "coinspect/planning/meeting_allocation.h"
#include "coinspect/planning/meeting_route.h"
#include "coinspect/planning/meeting_sampling.h"

namespace coinspect::planning {

struct MeetingOptions {
  MeetingSamplingOptions sampling;  // range 5 m, 1 m margin, 0.4 m grid, <= 1000 per pose
  double inspectionTime = 3.0;      // s, t_q
  TravelLimits explorerLimits;      // a = 1 m/s^2, v = 2 m/s in the reference's cost model
  TravelLimits inspectorLimits;
  MeetingGaOptions ga;       // population 20, 100 generations, mutation 0.01, 2 elites
  int maxInspectorsMet = 0;  // largest subset tried; 0: automatic (see above)
  uint64_t seed = 1;
};

struct MeetingProblem {
  ExplorerState explorer;
  std::vector<InspectorPlan> inspectors;  // the explorer's inspectors, each with >= 1 pose
  std::vector<PendingFeature> features;   // found, not yet handed to anyone
  bool explorationFinished = false;       // then a meeting is mandatory
};

struct PlannedMeeting {
  int inspector = 0;    // index into MeetingProblem::inspectors
  int inspectorId = 0;  // its InspectorPlan::id
  int pose = 0;         // the planned pose the meeting point was sampled around
  Vec3 point = Vec3::Zero();
  double arrival = 0.0;             // s, when the explorer planned to reach the point
  double meetingTime = 0.0;         // s, max(arrival, that pose's window start)
  std::vector<int64_t> featureIds;  // handed to the inspector, in its visiting order
  double inspectorStart = 0.0;      // s, when it is planned to start on them
  double inspectorFinish = 0.0;     // s, when it is planned to finish them
};

enum class MeetingChoice {
  NoMeeting,         // not meeting is cheaper (exploring), or there is nothing to hand over
  Meet,              // meet `meetings`, in order
  NoFeasibleMeeting  // every candidate misses a time window or has no meeting point
};

struct MeetingDecision {
  MeetingChoice choice = MeetingChoice::NoMeeting;
  std::vector<PlannedMeeting> meetings;  // the best candidate's, when choice == Meet
  // s; both stay +infinity when no candidate was feasible or none was evaluated
  double meetingCost = std::numeric_limits<double>::infinity();  // the best candidate's
  double noMeetingCost = std::numeric_limits<double>::infinity();
  double rightAxis = 0.0;  // s, the best candidate's R
  int candidates = 0;      // subset orders evaluated
  int feasibleCandidates = 0;
};

// Throws InputError for bad options (each stage's validation, and a negative maxInspectorsMet).
void validateMeetingOptions(const MeetingOptions& options);

// How many inspectors one decision may meet at most (see the deviations above).
int meetingSubsetLimit(int inspectors, int features, const MeetingOptions& options);

// points[i][p]: sampleMeetingPoints around inspectors[i].poses[p], empty when that window ended
// before `now`.
std::vector<InspectorMeetingPoints> sampleInspectorMeetingPoints(
    const std::vector<InspectorPlan>& inspectors, double now, const MeetingBox& box,
    const MeetingSpace& space, const MeetingSamplingOptions& options);

// The decision on precomputed candidate points (points[i] for problem.inspectors[i]).
MeetingDecision decideMeetings(const MeetingProblem& problem,
                               const std::vector<InspectorMeetingPoints>& points,
                               const MeetingOptions& options);

// Samples the points in `box` with `space`, then decides.
MeetingDecision decideMeetings(const MeetingProblem& problem, const MeetingBox& box,
                               const MeetingSpace& space, const MeetingOptions& options);

}  // namespace coinspect::planning
