// Time parametrisation of a polyline within speed and acceleration limits, for streaming
// setpoints (position, velocity, acceleration) at any rate.
//
// Each interior vertex is rounded by a parabolic blend: the trajectory leaves the incoming
// segment b before the vertex at the corner speed v and joins the outgoing one b after it, with
// constant acceleration of magnitude maxAcceleration in between (b = v^2 sin(theta/2) / a_max for
// a turn of theta). The blend is a quadratic Bezier curve with the vertex as its control point:
// it stays inside the triangle (vertex - b u_in, vertex, vertex + b u_out) and passes
// v^2 sin^2(theta/2) / (2 a_max) from the vertex. The corner speed is the largest v that keeps
// that distance <= cornerTolerance, both blends within half of each adjacent segment, and the
// speed limits; between blends each straight stretch accelerates, cruises and brakes at a_max
// (a forward and a backward pass make the corner speeds reachable). Every piece has constant
// acceleration, so speed <= the limit and |acceleration| <= maxAcceleration hold everywhere.
#pragma once

#include <vector>

#include "coinspect/mapping/voxel_grid.h"

namespace coinspect::planning {

using mapping::Vec3;

struct TrajectoryLimits {
  double maxSpeed = 2.0;         // m/s
  double maxAcceleration = 1.0;  // m/s^2
  double cornerTolerance = 0.2;  // m, largest distance the blend may pass from a vertex
  double startSpeed = 0.0;       // m/s along the first segment (0: start at rest)
  double endSpeed = 0.0;         // m/s along the last segment (0: stop at the end)
  // Optional per-segment speed limits (segment i joins input vertices i and i + 1; empty or
  // size = vertices - 1), e.g. blurFreeSpeed on inspection stretches.
  std::vector<double> segmentSpeeds;
};

struct TrajectorySample {
  Vec3 position = Vec3::Zero();
  Vec3 velocity = Vec3::Zero();
  Vec3 acceleration = Vec3::Zero();
};

class Trajectory {
 public:
  Trajectory() = default;
  // Consecutive vertices closer than 1e-9 m are merged. Limits must be positive (speeds >= 0).
  // A start speed that cannot be braked to the end speed within the path is lowered (see
  // startSpeed()): give paths long enough for the speed the robot has.
  Trajectory(const std::vector<Vec3>& polyline, const TrajectoryLimits& limits);

  double duration() const { return duration_; }
  // Clamped to [0, duration()]: before, the start state; after, the end point with the end
  // velocity and zero acceleration.
  TrajectorySample sample(double t) const;
  double startSpeed() const { return startSpeed_; }
  // The polyline after merging duplicates (the blends cut its corners).
  const std::vector<Vec3>& vertices() const { return vertices_; }

 private:
  struct Piece {  // constant acceleration from (position, velocity) at time start
    double start, duration;
    Vec3 position, velocity, acceleration;
  };
  void addPiece(const Vec3& position, const Vec3& velocity, const Vec3& acceleration,
                double duration);
  void addStraight(const Vec3& from, const Vec3& direction, double length, double v0, double v1,
                   double vmax, double amax);

  std::vector<Vec3> vertices_;
  std::vector<Piece> pieces_;
  double duration_ = 0.0;
  double startSpeed_ = 0.0;
  Vec3 endVelocity_ = Vec3::Zero();
};

}  // namespace coinspect::planning
