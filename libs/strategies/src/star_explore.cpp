#include "coinspect/strategies/star/star_explore.h"

#include <algorithm>
#include <cmath>

#include "coinspect/planning/coverage.h"
#include "coinspect/planning/routing_tsp.h"

namespace coinspect::strategies::star {

std::vector<Vec3> ringCandidates(const Vec3& centre, const RingOptions& options) {
  std::vector<Vec3> out;
  const int count = std::max(1, options.perRing);
  for (const double radius : options.radii)
    for (const double height : options.heights)
      for (int k = 0; k < count; ++k) {
        const double angle = 2.0 * M_PI * k / count;
        const Vec3 p = centre + Vec3(radius * std::cos(angle), radius * std::sin(angle), height);
        if (p.z() >= options.minZ) out.push_back(p);
      }
  return out;
}

size_t visibleCells(const mapping::VoxelGrid& grid, const Vec3& from,
                    const std::vector<Vec3>& cells, double range) {
  size_t seen = 0;
  for (const auto& cell : cells)
    if ((cell - from).norm() <= range && planning::freeLineOfSight(grid, from, cell)) ++seen;
  return seen;
}

std::optional<RingViewpoint> bestRingViewpoint(const mapping::FrontierCluster& cluster,
                                               const mapping::VoxelGrid& grid,
                                               const RingOptions& options) {
  // An even sample of the cells keeps the cost bounded on large clusters.
  std::vector<Vec3> sample;
  const size_t step =
      std::max<size_t>(1, cluster.cells.size() / std::max<size_t>(1, options.maxCells));
  for (size_t i = 0; i < cluster.cells.size(); i += step)
    sample.push_back(cluster.cells[i]);
  std::optional<RingViewpoint> best;
  for (const auto& candidate : ringCandidates(cluster.centroid, options)) {
    const auto cell = grid.cellOf(candidate);
    if (!grid.contains(cell) || grid.state(cell) != mapping::CellState::Free) continue;
    if (grid.hasClearance() && grid.clearance(cell) < options.clearance) continue;
    const size_t seen = visibleCells(grid, candidate, sample, options.range);
    if (seen == 0 || (best && seen <= best->seen)) continue;
    const Vec3 d = cluster.centroid - candidate;
    best = RingViewpoint{Pose{candidate, std::atan2(d.y(), d.x())}, seen};
  }
  return best;
}

double yawChange(double a, double b) {
  return std::abs(std::remainder(b - a, 2.0 * M_PI));
}

std::vector<size_t> atspOrder(const Pose& start, const std::vector<Pose>& poses, double yawWeight) {
  const int n = static_cast<int>(poses.size()) + 1;
  planning::CostMatrix costs(n, 0.0);
  const auto poseOf = [&](int i) { return i == 0 ? start : poses[static_cast<size_t>(i - 1)]; };
  for (int a = 0; a < n; ++a)
    for (int b = 1; b < n; ++b) {
      if (a == b) continue;
      const Pose from = poseOf(a), to = poseOf(b);
      // The heading a leg needs: first turn to fly along it (the body faces its travel), then
      // to the viewpoint's heading; asymmetric because the start heading is the robot's.
      const Vec3 d = to.position - from.position;
      const double travelYaw =
          std::hypot(d.x(), d.y()) > 1e-6 ? std::atan2(d.y(), d.x()) : from.yaw;
      const double turn = yawChange(from.yaw, travelYaw) + yawChange(travelYaw, to.yaw);
      costs.set(a, b, d.norm() + yawWeight * turn);
    }
  for (int a = 1; a < n; ++a)
    costs.set(a, 0, 0.0);  // an open tour never comes back
  planning::LocalSearchOptions search;
  search.maxEvaluations = 200000;
  const auto tour = planning::solveTsp(costs, {planning::TourKind::Open, 0, -1}, search);
  std::vector<size_t> order;
  for (size_t k = 1; k < tour.order.size(); ++k)
    order.push_back(static_cast<size_t>(tour.order[k] - 1));
  return order;
}

}  // namespace coinspect::strategies::star
