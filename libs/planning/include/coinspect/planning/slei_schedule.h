// Two pure pieces of SLEI3D's ground-station (GCS) layer: when an explorer expects to be done
// with its box (the paper's eq. 9, as the reference code computes it), and at which corner of the
// box the GCS meets it. The order in which the GCS drives to its meetings is in
// slei_meeting_order.h.
//
// Reference: TRIO-PKU/SLEI3D, exp_meeting_manager.py `predict_finish_time` and
// gcs_meeting_manager.py `find_nearest_verticie`.
#pragma once

#include <array>
#include <functional>
#include <vector>

#include "coinspect/mapping/voxel_grid.h"

namespace coinspect::planning {

using mapping::Vec3;

// ---------------------------------------------------------------------------------------------
// Task-completion prediction

struct CompletionPredictionOptions {
  double minRemaining = 50.0;          // s, lower clamp (the reference's floor)
  double maxRemaining = 600.0;         // s, upper clamp (the reference caps what it sends)
  double uninspectedFallback = 100.0;  // s, features expected but none inspected yet
  double explorerSpeed = 2.5;          // m/s, for the closing tour (the launch files' value)
};

// What an explorer knows about its current box when it calls the GCS.
struct CompletionInputs {
  double boxVolume = 0.0;       // m^3, V_b, from the box bounds
  double exploredVolume = 0.0;  // m^3, V_e, known (free or occupied) volume inside the box
  int featuresScanned = 0;      // N_s, features the explorer detected in this box
  int featuresInspected = 0;    // N_r, reported inspected by its inspectors since the box began
  double timeInBox = 0.0;       // s, t_e = now - the moment the explorer reached the box
  // s, the flying time of the sweep it has planned (0: none); read when nothing is explored
  // yet, where eq. 9 has nothing to extrapolate from.
  double plannedSweepTime = 0.0;
  // The box's features are handed out only once it is explored (`handout_at_box_end`): none is
  // inspected while it is explored, so the box is done when it is explored, and the inspections
  // give no rate to extrapolate.
  bool inspectedAfterExploration = false;
  bool explorationFinished = false;
  // Only read when explorationFinished:
  double earliestInspectorFinish = 0.0;  // s, absolute: the soonest planned end of an inspector
  double closingTourLength = 0.0;        // m, explorer -> each inspector's last planned pose
  double now = 0.0;                      // s
};

// Which case of the prediction gave the time (see predictCompletion).
enum class CompletionRule {
  NothingExplored,          // V_e = 0: the planned sweep's time, else the lower clamp
  VolumeExtrapolation,      // no features, or all predicted features already scanned
  UninspectedFallback,      // features still to find, none inspected yet
  InspectionExtrapolation,  // features still to find, progress measured by inspections
  ClosingTour               // exploration finished: wait for an inspector, then visit them all
};

struct CompletionPrediction {
  double remaining = 0.0;  // s, from now, clamped to [minRemaining, maxRemaining]
  double unclamped = 0.0;  // s, the case's own value before the clamps
  CompletionRule rule = CompletionRule::NothingExplored;
};

// The remaining time before the explorer's box is done, by the first case that applies:
//   exploration finished (ClosingTour):
//     t* = max(earliestInspectorFinish, now);  T = t* + closingTourLength / explorerSpeed - now
//     (the reference then waits for its inspectors and collects their results on the way).
//   V_e = 0 (NothingExplored): T = minRemaining (the reference's literal 50 s).
//   otherwise N_pred = floor(N_s V_b / V_e), the features the box holds at the density seen so
//   far (computed as one quotient, not rho * V_b, so that exact ratios do not round down), and
//     N_s = 0, N_s >= N_pred or inspectedAfterExploration (VolumeExtrapolation):
//       T = (V_b / V_e) t_e - t_e; the rest of the box takes as long per cubic metre as the part
//       explored;
//     N_r = 0 (UninspectedFallback): T = uninspectedFallback;
//     else (InspectionExtrapolation): T = (N_pred / N_r) t_e - t_e; inspections go on at the
//       rate seen so far until all predicted features are done.
// T is then clamped to [minRemaining, maxRemaining] (an explored volume above the box volume
// gives a negative T, which the lower clamp catches). The reference's third case (box closed:
// the whole time spent) is dead code there and not modelled: a closed box needs no prediction.
// Throws InputError (source "completion prediction") for negative or non-finite volumes, counts,
// times or tour length, minRemaining > maxRemaining, a negative clamp or fallback, or a
// non-positive explorer speed.
CompletionPrediction predictCompletion(const CompletionInputs& inputs,
                                       const CompletionPredictionOptions& options = {});

// Length of the straight tour start -> stops[0] -> stops[1] -> ..., in the order given. The
// reference measures it in XY only (horizontalOnly = true): the explorer's altitude changes are
// ignored.
double straightTourLength(const Vec3& start, const std::vector<Vec3>& stops,
                          bool horizontalOnly = true);

// ---------------------------------------------------------------------------------------------
// FF3E's bound: exploration that still reaches the next meeting on time

// The stops an explorer at `start` at time `now` can fly, nearest first from the last one, such
// that from each it still reaches `meeting` by `deadline` (the paper's Alg. 1 bounds its
// frontier sequences by the meeting time; this is its greedy form, replanned in receding
// horizon by the caller). A stop that does not fit is skipped (a later, nearer-the-meeting one
// may). Times: straight lines at `speed`, times `travelFactor` (paths are longer). Returns the
// indices of the stops kept, in flying order; all of them, nearest first, when `deadline` is
// infinite.
std::vector<size_t> deadlineBoundedTour(const Vec3& start, double now,
                                        const std::vector<Vec3>& stops, const Vec3& meeting,
                                        double deadline, double speed, double travelFactor = 1.0);

// FF3E's recursive search, our form: of the sequences of up to `depth` stops (at each step one of
// the `branching` nearest not yet taken that still lets the explorer reach `meeting` by
// `deadline`), the one that gains the most per second (the sum of `gains`, e.g. the surface each
// stop's view sweeps, over the flying time plus `dwell` s a stop; ties to the shorter), then
// deadlineBoundedTour's nearest-first stops from its end: the caller flies it and searches
// again later (receding horizon). Times as deadlineBoundedTour's. Depth 0: deadlineBoundedTour.
// Throws InputError when `gains` does not match `stops` or a gain is negative or not finite.
struct FrontierSearchOptions {
  size_t depth = 3;
  size_t branching = 6;
  double dwell = 0.0;  // s at each stop
  double travelFactor = 1.0;
};
std::vector<size_t> deadlineBoundedSearch(const Vec3& start, double now,
                                          const std::vector<Vec3>& stops,
                                          const std::vector<double>& gains, const Vec3& meeting,
                                          double deadline, double speed,
                                          const FrontierSearchOptions& options);

// ---------------------------------------------------------------------------------------------
// Meeting place: a corner of the box footprint

struct MeetingCornerOptions {
  double inset = 1.0;   // m, moved into the box in x and in y
  double height = 0.5;  // m, z of the meeting point (the GCS drives on the ground)
};

// The 4 corners of the footprint of the axis-aligned box [boxMin, boxMax], inset in x and y, at
// options.height, in the order (min x, min y), (max x, min y), (max x, max y), (min x, max y).
// When the box is narrower than 2 insets along an axis, both corners sit on its middle line
// there. Throws InputError (source "meeting corners") for boxMin above boxMax in x or y, a
// negative inset or non-finite values.
std::array<Vec3, 4> meetingCorners(const Vec3& boxMin, const Vec3& boxMax,
                                   const MeetingCornerOptions& options = {});

struct MeetingCornerChoice {
  int index = -1;  // into meetingCorners(); -1 when no corner is reachable (timed choice only)
  Vec3 point = Vec3::Zero();
  double arrival = 0.0;  // s, the GCS's arrival there (timed choice only)
};

// The reference's rule: the corner nearest, in XY, to `reference` (the previous meeting point, or
// the mean of the GCS's pending meetings); ties go to the first corner in the order above.
MeetingCornerChoice nearestMeetingCorner(const Vec3& boxMin, const Vec3& boxMax,
                                         const Vec3& reference,
                                         const MeetingCornerOptions& options = {});

// The paper's rule: the corner whose arrival time best matches the planned meeting time, i.e.
// with the least |arrivalTime(corner) - plannedTime|; ties go to the earlier arrival, then to the
// first corner. arrivalTime gives the GCS's (absolute) arrival at a corner, e.g. now + an A*
// path's length / speed; +infinity or NaN marks a corner it cannot reach, which is never chosen.
MeetingCornerChoice bestTimedMeetingCorner(const Vec3& boxMin, const Vec3& boxMax,
                                           const std::function<double(const Vec3&)>& arrivalTime,
                                           double plannedTime,
                                           const MeetingCornerOptions& options = {});

}  // namespace coinspect::planning
