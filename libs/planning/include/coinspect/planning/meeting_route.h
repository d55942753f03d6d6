// Where an explorer meets a given sequence of inspectors (SLEI3D's "OptMeet"): a genetic
// algorithm picks one meeting point per inspector among its candidates (meeting_sampling.h) so
// that explorer travel + explorer waiting + inspector waiting is least, every meeting falling in
// the time window of the pose it was sampled around.
//
// Timeline of a route, from the explorer's position at `now`, for each inspector in order:
//   arrival       = departure + travelTime(|point - previous point|, explorer limits)
//   infeasible    when arrival > window end
//   meeting time  = max(arrival, window start)        (the explorer waits for the inspector)
//   explorer wait = meeting time - arrival
//   inspector wait= open window (last pose, end = +inf):
//                     max(0, arrival - max(now, window start + t_q))
//                   closed window: 0 (the inspector is still hovering or travelling anyway)
//   departure     = meeting time (the exchange itself is taken as instantaneous)
//   cost          = sum of travel + explorer wait + inspector wait; +infinity if infeasible.
// The reference advances its clock by travel only, letting the explorer leave a meeting before
// the inspector has come; here the clock waits (departure = meeting time).
#pragma once

#include <cstdint>
#include <limits>
#include <vector>

#include "coinspect/mapping/voxel_grid.h"
#include "coinspect/planning/travel_time.h"

namespace coinspect::planning {

using mapping::Vec3;

inline constexpr double kOpenWindowEnd = std::numeric_limits<double>::infinity();

// One planned hover of an inspector: it reaches `position` at `start` and leaves at `end`.
struct HoverWindow {
  Vec3 position = Vec3::Zero();
  double start = 0.0;           // s
  double end = kOpenWindowEnd;  // s; +infinity for the last pose, where it stays
};

struct InspectorPlan {
  int id = 0;                      // the caller's identifier, copied into decisions
  std::vector<HoverWindow> poses;  // in plan order, at least one; the last is where it stays
};

struct ExplorerState {
  Vec3 position = Vec3::Zero();
  double now = 0.0;  // s
};

// Candidate meeting points of one inspector: points[p] are those around its pose p (possibly
// none, e.g. for a pose whose window has passed).
using InspectorMeetingPoints = std::vector<std::vector<Vec3>>;

struct MeetingGaOptions {
  int population = 20;  // at least this, and at least the largest pose count
  int generations = 100;
  double mutationRate = 0.01;  // per gene
  int elites = 2;              // best individuals copied unchanged into the next generation
  // Most coordinate-descent sweeps after the GA (not in the reference; 0: the reference's GA).
  int polishSweeps = 3;
};

struct MeetingRouteOptions {
  double inspectionTime = 3.0;  // s, t_q: an inspector's hover at a pose
  TravelLimits explorer;        // the explorer's trapezoid profile
  MeetingGaOptions ga;
};

// Throws InputError (source "meeting route options") for a population or generation count below
// 1 and 0, a mutation rate outside [0, 1], negative elites, a negative inspection time or
// non-positive travel limits.
void validateMeetingRoute(const MeetingRouteOptions& options);

// Which candidate an inspector is met at: points[pose][sample].
struct MeetingPick {
  int pose = 0;
  int sample = 0;
};

struct MeetingStop {
  int inspector = 0;  // index into the inspectors vector
  MeetingPick pick;
  Vec3 point = Vec3::Zero();
  double arrival = 0.0;      // s, when the explorer reaches the point
  double meetingTime = 0.0;  // s, max(arrival, window start)
  double explorerWait = 0.0;
  double inspectorWait = 0.0;
  bool feasible = true;  // arrival <= window end
};

struct MeetingRoute {
  std::vector<MeetingStop> stops;  // in visiting order; empty when an inspector has no candidate
  double cost = std::numeric_limits<double>::infinity();
  bool feasible() const { return cost < std::numeric_limits<double>::infinity(); }
};

// The timeline and cost of meeting inspectors[order[k]] at picks[k], k = 0, 1, ...
// Throws InputError for mismatched sizes, an index out of range or an empty plan.
MeetingRoute evaluateMeetingRoute(const ExplorerState& explorer,
                                  const std::vector<InspectorPlan>& inspectors,
                                  const std::vector<InspectorMeetingPoints>& points,
                                  const std::vector<int>& order,
                                  const std::vector<MeetingPick>& picks,
                                  const MeetingRouteOptions& options);

// The GA: one gene per inspector of `order` (a candidate of that inspector). Individual i starts
// at pose (i mod pose count) with a random sample of it (any candidate if that pose has none);
// each generation ranks by cost (ties by index), keeps the better half as parents, copies the
// elites, and fills the rest with single-point crossovers of two random parents, each gene then
// replaced with probability mutationRate by a random candidate of any pose. The best route seen
// is then polished (polishSweeps > 0): coordinate descent, each gene in turn set to the candidate
// that makes the whole route cheapest with the others fixed, until a sweep changes nothing; the
// same from a greedy route (each inspector at its cheapest next leg); the cheaper result wins.
// The GA alone tries only a few dozen of an inspector's up to thousands of candidates and often
// stops well short of the optimum; the polish is exact per gene and prunes whole poses by a lower
// bound, so it costs little. With an inspector that has no candidate at all: no stops, infinite
// cost. Deterministic for a seed.
MeetingRoute optimiseMeetingRoute(const ExplorerState& explorer,
                                  const std::vector<InspectorPlan>& inspectors,
                                  const std::vector<InspectorMeetingPoints>& points,
                                  const std::vector<int>& order, const MeetingRouteOptions& options,
                                  uint64_t seed);

}  // namespace coinspect::planning
