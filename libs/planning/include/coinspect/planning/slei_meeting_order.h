// The order in which SLEI3D's ground station (GCS) drives to its meetings with the explorers: a
// travelling-salesman path with time windows (TSP-TW), as the paper states it. The reference code
// instead serves its meetings sorted by planned time, which can make the GCS shuttle back and
// forth or miss a window a better order meets (evaluateMeetingOrder scores any given order, so
// the two can be compared).
//
// Timeline of an order, from `startTime` at `start`, for each meeting m in turn:
//   arrival   = previous departure + travelTime(previous place, m.place)
//   start     = max(arrival, m.earliest)       (the GCS waits when early)
//   lateness  = max(0, arrival - m.latest)     (a late GCS starts at once; an unreachable
//                                               meeting, infinite travel, is infinitely late)
//   departure = start + m.service
// An order meets every window when no lateness is positive. Orders are ranked by
//   (largest lateness, total lateness, completion = departure from the last meeting),
// compared in that order: among orders that meet every window the earliest completion wins, and
// when none does, the least late one (a soft fallback, so an order is always returned).
//
// Exact for at most `exactLimit` meetings (12 by default): dynamic programming over (set of
// meetings served, last one) keeping, per state, the labels (departure, largest lateness, total
// lateness) that no other label beats in all three; each only grows along an order, so a beaten
// label can never lead to a better order. It first runs with hard windows (one label per state:
// the earliest departure), and only when no order meets every window with soft ones, pruned by
// the heuristic's largest lateness. Up to 12 meetings it takes milliseconds, 16 under a second.
// Beyond the limit: insertion by deadline (each meeting where the rank is best), then pairwise
// swaps, moves of single meetings and reversals of stretches while they improve the rank (on
// random instances of 12 meetings it matches the optimum about 60 % of the time, completion
// within 9 %, and agrees on feasibility in at least 99 of 100).
#pragma once

#include <functional>
#include <limits>
#include <vector>

#include "coinspect/mapping/voxel_grid.h"

namespace coinspect::planning {

using mapping::Vec3;

// Travel time of the GCS between two points, s: must be >= 0 (may be +infinity: unreachable)
// and depend on the two points only.
using GcsTravelTime = std::function<double(const Vec3& from, const Vec3& to)>;

// Straight line on the ground (XY distance, the GCS is a ground vehicle) at `speed` m/s. Throws
// InputError for a non-positive speed.
GcsTravelTime groundTravelTime(double speed = 1.0);

struct GcsMeeting {
  int id = 0;  // the caller's identifier (e.g. the explorer's), copied into the schedule
  Vec3 place = Vec3::Zero();
  double earliest = 0.0;                                    // s, the explorer is there from then
  double latest = std::numeric_limits<double>::infinity();  // s, the meeting must start by then
  double service = 0.0;                                     // s, how long the meeting holds the GCS
};

struct MeetingOrderProblem {
  Vec3 start = Vec3::Zero();  // where the GCS is
  double startTime = 0.0;     // s, when it can leave
  std::vector<GcsMeeting> meetings;
  GcsTravelTime travelTime;  // empty: groundTravelTime(1.0), the reference's gcs_max_vel
};

struct MeetingOrderOptions {
  int exactLimit = 12;         // dynamic programming up to this many meetings (at most 16)
  int improvementPasses = 50;  // most improvement passes of the heuristic
};

struct ScheduledMeeting {
  int meeting = 0;         // index into MeetingOrderProblem::meetings
  int id = 0;              // its GcsMeeting::id
  double arrival = 0.0;    // s
  double start = 0.0;      // s, max(arrival, earliest)
  double departure = 0.0;  // s, start + service
  double lateness = 0.0;   // s, max(0, arrival - latest)
};

struct MeetingSchedule {
  std::vector<int> order;               // indices into MeetingOrderProblem::meetings
  std::vector<ScheduledMeeting> stops;  // the same, in visiting order, with their times
  bool allWindowsMet = true;
  double completion = 0.0;     // s, departure from the last meeting (startTime when none)
  double maxLateness = 0.0;    // s
  double totalLateness = 0.0;  // s
  bool exact = false;          // found by the dynamic programme
};

// Throws InputError (source "meeting order") for non-finite start values, a meeting with a
// non-finite earliest time, latest < earliest, a negative or non-finite service time, options
// outside their ranges, or a travel time that is negative or NaN.
void validateMeetingOrderProblem(const MeetingOrderProblem& problem,
                                 const MeetingOrderOptions& options = {});

// The best order: exact up to options.exactLimit meetings, heuristic beyond.
MeetingSchedule planMeetingOrder(const MeetingOrderProblem& problem,
                                 const MeetingOrderOptions& options = {});

// The dynamic programme alone (throws InputError above 16 meetings). Among equally ranked orders
// it keeps the first found: sets in increasing bitmask order, last meetings by increasing index.
MeetingSchedule exactMeetingOrder(const MeetingOrderProblem& problem);

// The insertion + improvement heuristic alone (deterministic: ties keep the earlier position).
MeetingSchedule heuristicMeetingOrder(const MeetingOrderProblem& problem,
                                      const MeetingOrderOptions& options = {});

// The timeline and rank of a given order (a permutation of the meeting indices; throws
// InputError otherwise), e.g. the reference's order by planned time.
MeetingSchedule evaluateMeetingOrder(const MeetingOrderProblem& problem,
                                     const std::vector<int>& order);

// True when `a` ranks strictly before `b` (largest lateness, total lateness, completion), each
// compared with `tolerance` seconds of slack.
bool ranksBefore(const MeetingSchedule& a, const MeetingSchedule& b, double tolerance = 1e-9);

}  // namespace coinspect::planning
