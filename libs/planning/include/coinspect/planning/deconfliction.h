// Inter-UAV deconfliction by priority: the robot with the lower fleet index has the right of
// way, and each robot yields only to robots of higher priority (lower index). A robot compares its
// desired plan with the plans its higher-priority neighbours announced (or, without an
// announcement, their known positions held or extrapolated) over a horizon and picks the first of:
//
//   Proceed   the desired plan keeps the separation;
//   Wait d    hold the current position for d (smallest multiple of step <= maxWait), then fly
//             the desired plan delayed by d;
//   Sidestep  move straight to one of 10 points `sidestep` m away (8 horizontal directions, up,
//             down) at sidestepSpeed and hold there; among those that keep the separation (and
//             pass the caller's segment check), the one nearest the desired plan's last point;
//   Hold      nothing works: hold and let the higher-priority robots avoid nothing (best effort).
//
// "Keeps the separation" means: over [now, now + horizon], with both motions linear between
// samples (the minimum distance on each interval is exact) and each robot holding after its
// plan ends, the distance never falls below min(separation, the current distance) - a pair that
// is already too close may separate but never close in.
//
// Why it works in the tick model: the highest-priority robot never yields; every other robot, at
// every decision (>= 10 Hz), commits to a plan that keeps the separation from every
// higher-priority plan over the horizon. A conflict first becomes visible `horizon` before it
// happens, so as long as horizon exceeds the time of a sidestep (sidestep / sidestepSpeed) plus
// one decision period and some sidestep is free, the lower robot gets out of the way in time;
// the separation must include the tracking error and braking distance of both robots, since
// plans are flown by a controller, not teleported. Ties are impossible (priorities are distinct).
#pragma once

#include <cstddef>
#include <functional>
#include <vector>

#include "coinspect/mapping/voxel_grid.h"
#include "coinspect/planning/trajectory.h"

namespace coinspect::planning {

// Positions at startTime + k step (linear in between); before startTime the robot is at the first
// position, after the last sample it holds there.
struct TimedPath {
  double startTime = 0.0;
  double step = 0.1;
  std::vector<Vec3> positions;

  Vec3 at(double t) const;
  static TimedPath hold(double time, const Vec3& position);
  static TimedPath constantVelocity(double time, const Vec3& position, const Vec3& velocity,
                                    double horizon, double step);
  // `trajectory` started at trajectoryStart; sampled from `from` for `horizon` s.
  static TimedPath fromTrajectory(const Trajectory& trajectory, double trajectoryStart, double from,
                                  double horizon, double step);
};

struct Neighbour {
  size_t priority = 0;  // fleet index: lower has the right of way
  TimedPath path;
};

struct DeconflictionOptions {
  double separation = 2.0;     // m between robot centres
  double horizon = 8.0;        // s
  double step = 0.1;           // s between plan samples
  double maxWait = 6.0;        // s
  double sidestep = 3.0;       // m
  double sidestepSpeed = 1.0;  // m/s
};

enum class YieldAction { Proceed, Wait, Sidestep, Hold };
const char* toString(YieldAction action);

struct DeconflictionResult {
  YieldAction action = YieldAction::Hold;
  double wait = 0.0;                   // Wait: s
  Vec3 sidestepTarget = Vec3::Zero();  // Sidestep
  TimedPath plan;                      // the chosen plan over the horizon (to fly and announce)
};

// `desired` starts at `now` at (about) `position`. `segmentFree(a, b)`, when given, vets sidestep
// moves against the map (e.g. segmentTraversable on the robot's grid).
DeconflictionResult deconflict(
    size_t ownPriority, double now, const Vec3& position, const TimedPath& desired,
    const std::vector<Neighbour>& neighbours, const DeconflictionOptions& options,
    const std::function<bool(const Vec3&, const Vec3&)>& segmentFree = nullptr);

}  // namespace coinspect::planning
