#include "coinspect/strategies/coinspect/gcs_contact.h"

#include <algorithm>

namespace coinspect::strategies::coinspect_strategy {

void GcsContact::observe(const agent::AgentView& view) {
  for (const auto& capture : view.captures)
    undelivered_ += capture.scoreGained;
  inContact_ = std::any_of(view.neighbours.begin(), view.neighbours.end(),
                           [](const auto& n) { return n.role == agent::Role::GroundStation; });
  if (!inContact_) return;
  // The station merges the whole on-board log while in sight: everything so far is delivered.
  undelivered_ = 0.0;
  lastContact_ = view.missionTime;
  const Vec3& here = view.odometry.position;
  const bool known = std::any_of(points_.begin(), points_.end(), [&](const Vec3& point) {
    return (point - here).norm() < options_.spacing;
  });
  if (!known) points_.push_back(here);
}

std::optional<Vec3> GcsContact::nearestContactPoint(const Vec3& from) const {
  if (points_.empty()) return std::nullopt;
  return *std::min_element(points_.begin(), points_.end(), [&](const Vec3& a, const Vec3& b) {
    return (a - from).squaredNorm() < (b - from).squaredNorm();
  });
}

bool GcsContact::shouldDeliver(const agent::AgentView& view) const {
  if (inContact_ || !view.started) return false;
  const auto target = nearestContactPoint(view.odometry.position);
  if (!target) return false;
  const double travel = (*target - view.odometry.position).norm() / options_.assumedSpeed;
  if (view.timeLeft <= travel + options_.endMargin) return true;
  return undelivered_ >= options_.minGain && view.missionTime - lastContact_ >= options_.period;
}

}  // namespace coinspect::strategies::coinspect_strategy
