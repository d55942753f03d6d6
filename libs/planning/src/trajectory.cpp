#include "coinspect/planning/trajectory.h"

#include <algorithm>
#include <cmath>

#include "coinspect/core/error.h"

namespace coinspect::planning {

Trajectory::Trajectory(const std::vector<Vec3>& polyline, const TrajectoryLimits& limits) {
  const double amax = limits.maxAcceleration;
  COINSPECT_ASSERT(limits.maxSpeed > 0.0 && amax > 0.0 && limits.cornerTolerance >= 0.0);
  COINSPECT_ASSERT(limits.startSpeed >= 0.0 && limits.endSpeed >= 0.0);
  COINSPECT_ASSERT(limits.segmentSpeeds.empty() ||
                   limits.segmentSpeeds.size() + 1 == polyline.size());
  // Merge duplicates, keeping the speed limit of each surviving segment.
  std::vector<double> segmentLimit;
  for (size_t i = 0; i < polyline.size(); ++i) {
    if (!vertices_.empty() && (polyline[i] - vertices_.back()).norm() < 1e-9) continue;
    if (!vertices_.empty()) {
      const double given =
          limits.segmentSpeeds.empty() ? limits.maxSpeed : limits.segmentSpeeds[i - 1];
      COINSPECT_ASSERT(given > 0.0);
      segmentLimit.push_back(std::min(limits.maxSpeed, given));
    }
    vertices_.push_back(polyline[i]);
  }
  const size_t n = vertices_.size();
  if (n < 2) return;
  const size_t m = n - 1;
  std::vector<Vec3> direction(m);
  std::vector<double> length(m);
  for (size_t i = 0; i < m; ++i) {
    const Vec3 delta = vertices_[i + 1] - vertices_[i];
    length[i] = delta.norm();
    direction[i] = delta / length[i];
  }
  // sin(theta / 2) of the turn at each vertex (0 at the ends: no blend there).
  std::vector<double> sinHalf(n, 0.0);
  std::vector<double> speed(n);
  speed[0] = std::min(limits.startSpeed, segmentLimit[0]);
  speed[m] = std::min(limits.endSpeed, segmentLimit[m - 1]);
  for (size_t k = 1; k < m; ++k) {
    sinHalf[k] = 0.5 * (direction[k] - direction[k - 1]).norm();
    double limit = std::min(segmentLimit[k - 1], segmentLimit[k]);
    if (sinHalf[k] > 1e-12) {
      limit = std::min(limit, std::sqrt(2.0 * amax * limits.cornerTolerance) / sinHalf[k]);
      limit = std::min(limit,
                       std::sqrt(amax * std::min(length[k - 1], length[k]) / (2.0 * sinHalf[k])));
    }
    speed[k] = limit;
  }
  const auto blend = [&](size_t k, double v) { return v * v * sinHalf[k] / amax; };
  const auto straight = [&](size_t i) {
    return std::max(0.0, length[i] - blend(i, speed[i]) - blend(i + 1, speed[i + 1]));
  };
  // Lowering a speed only shortens blends (lengthens straights), so one pass each way suffices.
  for (size_t i = 0; i < m; ++i)
    speed[i + 1] =
        std::min(speed[i + 1], std::sqrt(speed[i] * speed[i] + 2.0 * amax * straight(i)));
  for (size_t i = m; i-- > 0;)
    speed[i] =
        std::min(speed[i], std::sqrt(speed[i + 1] * speed[i + 1] + 2.0 * amax * straight(i)));
  startSpeed_ = speed[0];

  for (size_t i = 0; i < m; ++i) {
    const double b0 = blend(i, speed[i]);
    const double b1 = blend(i + 1, speed[i + 1]);
    addStraight(vertices_[i] + b0 * direction[i], direction[i], straight(i), speed[i], speed[i + 1],
                segmentLimit[i], amax);
    if (i + 1 < m && b1 > 0.0 && speed[i + 1] > 0.0) {
      const double v = speed[i + 1];
      const double time = 2.0 * b1 / v;
      addPiece(vertices_[i + 1] - b1 * direction[i], v * direction[i],
               v * (direction[i + 1] - direction[i]) / time, time);
    }
  }
  endVelocity_ = speed[m] * direction[m - 1];
}

void Trajectory::addPiece(const Vec3& position, const Vec3& velocity, const Vec3& acceleration,
                          double duration) {
  if (duration <= 0.0) return;
  pieces_.push_back({duration_, duration, position, velocity, acceleration});
  duration_ += duration;
}

// Accelerate from v0, cruise at most at vmax, brake to v1 over `length` (reachable by the passes).
void Trajectory::addStraight(const Vec3& from, const Vec3& direction, double length, double v0,
                             double v1, double vmax, double amax) {
  if (length <= 1e-12) return;
  const double peak =
      std::min(vmax, std::sqrt(std::max(0.0, (2.0 * amax * length + v0 * v0 + v1 * v1) / 2.0)));
  const double up = std::max(0.0, (peak * peak - v0 * v0) / (2.0 * amax));
  const double down = std::max(0.0, (peak * peak - v1 * v1) / (2.0 * amax));
  const double cruise = std::max(0.0, length - up - down);
  addPiece(from, v0 * direction, amax * direction, std::max(0.0, peak - v0) / amax);
  addPiece(from + up * direction, peak * direction, Vec3::Zero(), cruise / peak);
  addPiece(from + (up + cruise) * direction, peak * direction, -amax * direction,
           std::max(0.0, peak - v1) / amax);
}

TrajectorySample Trajectory::sample(double t) const {
  TrajectorySample out;
  if (pieces_.empty()) {
    if (!vertices_.empty()) out.position = vertices_.front();
    return out;
  }
  if (t >= duration_) {
    out.position = vertices_.back();
    out.velocity = endVelocity_;
    return out;
  }
  t = std::max(t, 0.0);
  // The last piece starting at or before t.
  const auto it =
      std::upper_bound(pieces_.begin(), pieces_.end(), t,
                       [](double time, const Piece& piece) { return time < piece.start; });
  const Piece& piece = *std::prev(it);
  const double tau = t - piece.start;
  out.position = piece.position + tau * piece.velocity + 0.5 * tau * tau * piece.acceleration;
  out.velocity = piece.velocity + tau * piece.acceleration;
  out.acceleration = piece.acceleration;
  return out;
}

}  // namespace coinspect::planning
