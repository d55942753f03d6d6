#include "coinspect/strategies/runtime/path_profile.h"

#include <algorithm>
#include <cmath>

#include "coinspect/core/error.h"

namespace coinspect::strategies::runtime {

PathProfile::PathProfile(std::vector<Vec3> points, const ProfileLimits& limits) : limits_(limits) {
  COINSPECT_ASSERT(limits.speed > 0.0 && limits.acceleration > 0.0 && limits.cornerSpeed >= 0.0);
  for (const auto& p : points)
    if (points_.empty() || (p - points_.back()).norm() > 1e-6) points_.push_back(p);
  if (points_.empty()) return;
  const size_t n = points_.size();
  cumulative_.assign(n, 0.0);
  for (size_t i = 1; i < n; ++i)
    cumulative_[i] = cumulative_[i - 1] + (points_[i] - points_[i - 1]).norm();
  // Corner speeds: full speed on a straight line, cornerSpeed at 90 degrees or more, the cosine
  // of the turn in between.
  vertexSpeed_.assign(n, limits.speed);
  vertexSpeed_.front() = 0.0;
  vertexSpeed_.back() = 0.0;
  for (size_t i = 1; i + 1 < n; ++i) {
    const Vec3 in = (points_[i] - points_[i - 1]).normalized();
    const Vec3 out = (points_[i + 1] - points_[i]).normalized();
    const double c = in.dot(out);
    vertexSpeed_[i] =
        std::clamp(limits.speed * c, std::min(limits.cornerSpeed, limits.speed), limits.speed);
  }
  // Leave the start at the speed the vehicle has (at least the corner speed, so that a vehicle
  // at rest gets going).
  vertexSpeed_.front() = std::min(std::max(limits.cornerSpeed, limits.startSpeed), limits.speed);
  const double a = limits.acceleration;
  for (size_t i = n - 1; i > 0; --i) {
    const double length = cumulative_[i] - cumulative_[i - 1];
    vertexSpeed_[i - 1] = std::min(vertexSpeed_[i - 1],
                                   std::sqrt(vertexSpeed_[i] * vertexSpeed_[i] + 2 * a * length));
  }
  for (size_t i = 1; i < n; ++i) {
    const double length = cumulative_[i] - cumulative_[i - 1];
    vertexSpeed_[i] = std::min(
        vertexSpeed_[i], std::sqrt(vertexSpeed_[i - 1] * vertexSpeed_[i - 1] + 2 * a * length));
  }
  finished_ = n < 2;
}

size_t PathProfile::segmentAt(double s) const {
  const auto it = std::upper_bound(cumulative_.begin(), cumulative_.end(), s);
  const size_t index = static_cast<size_t>(it - cumulative_.begin());
  return std::clamp<size_t>(index == 0 ? 0 : index - 1, 0, points_.size() - 2);
}

double PathProfile::speedAt(double s) const {
  if (points_.size() < 2) return 0.0;
  const size_t i = segmentAt(s);
  const double a = limits_.acceleration;
  const double fromStart = std::max(0.0, s - cumulative_[i]);
  const double toEnd = std::max(0.0, cumulative_[i + 1] - s);
  return std::min({limits_.speed, std::sqrt(vertexSpeed_[i] * vertexSpeed_[i] + 2 * a * fromStart),
                   std::sqrt(vertexSpeed_[i + 1] * vertexSpeed_[i + 1] + 2 * a * toEnd)});
}

Vec3 PathProfile::pointAt(double s) const {
  if (points_.size() < 2) return points_.empty() ? Vec3::Zero() : points_.front();
  const size_t i = segmentAt(s);
  const double length = cumulative_[i + 1] - cumulative_[i];
  const double t = length > 0.0 ? std::clamp((s - cumulative_[i]) / length, 0.0, 1.0) : 1.0;
  return points_[i] + t * (points_[i + 1] - points_[i]);
}

size_t PathProfile::nextVertex() const {
  if (finished_) return points_.size();
  return segmentAt(s_) + 1;
}

void PathProfile::advance(const Vec3& vehicle, double dt) {
  if (finished_ || dt <= 0.0) return;
  waiting_ = (vehicle - pointAt(s_)).norm() > limits_.maxLag;
  if (waiting_) return;
  // Midpoint rule over the step: the speed changes little within 0.1 s.
  const double v0 = std::max(speedAt(s_), 0.05);
  const double v1 = std::max(speedAt(std::min(length(), s_ + v0 * dt)), 0.05);
  s_ = std::min(length(), s_ + 0.5 * (v0 + v1) * dt);
  if (s_ >= length() - 1e-9) {
    s_ = length();
    finished_ = true;
  }
}

agent::AgentSetpoint PathProfile::setpoint() const {
  agent::AgentSetpoint out;
  out.position = pointAt(s_);
  if (!finished_ && !waiting_ && points_.size() >= 2) {
    const size_t i = segmentAt(s_);
    const Vec3 direction = (points_[i + 1] - points_[i]).normalized();
    out.velocity = speedAt(s_) * direction;
  }
  return out;
}

}  // namespace coinspect::strategies::runtime
