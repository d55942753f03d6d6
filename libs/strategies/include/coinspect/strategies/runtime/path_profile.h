// A polyline flown with a speed profile: the speed is capped everywhere, lowered at corners
// (the sharper, the slower) and shaped so that speeding up and slowing down never exceed the
// acceleration limit; the path ends at rest. A reference point ("carrot") moves along it in
// time; it waits when the vehicle lags too far behind, so a disturbed vehicle is never led away
// from the checked path.
#pragma once

#include <vector>

#include "coinspect/agent/commands.h"

namespace coinspect::strategies::runtime {

using agent::Vec3;

struct ProfileLimits {
  double speed = 2.0;         // m/s
  double acceleration = 1.0;  // m/s^2
  double cornerSpeed = 0.4;   // m/s at a right-angle or sharper corner
  double maxLag = 1.5;        // m: the carrot waits while the vehicle is farther than this
  double startSpeed = 0.0;    // m/s the vehicle already has (capped by the corner speed rule)
};

class PathProfile {
 public:
  PathProfile() = default;
  // Consecutive duplicate points are dropped; a single point is a hover there.
  PathProfile(std::vector<Vec3> points, const ProfileLimits& limits);

  bool empty() const { return points_.empty(); }
  bool finished() const { return finished_; }
  double length() const { return cumulative_.empty() ? 0.0 : cumulative_.back(); }
  double travelled() const { return s_; }
  const std::vector<Vec3>& points() const { return points_; }
  // Index of the first vertex not reached yet (points().size() when finished).
  size_t nextVertex() const;

  // Moves the carrot `dt` s ahead unless `vehicle` lags more than maxLag behind it.
  void advance(const Vec3& vehicle, double dt);
  // The setpoint at the carrot: position, velocity along the path (zero at the end and while the
  // carrot waits), no acceleration feed-forward; yaw is left for the caller.
  agent::AgentSetpoint setpoint() const;
  // Speed the profile allows at arc length s.
  double speedAt(double s) const;
  Vec3 pointAt(double s) const;

 private:
  size_t segmentAt(double s) const;

  std::vector<Vec3> points_;
  std::vector<double> cumulative_;   // arc length at each vertex
  std::vector<double> vertexSpeed_;  // allowed speed at each vertex after both passes
  ProfileLimits limits_;
  double s_ = 0.0;
  bool finished_ = true;
  bool waiting_ = false;  // the last advance() found the vehicle too far from the carrot
};

}  // namespace coinspect::strategies::runtime
