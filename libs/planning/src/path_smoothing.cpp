#include "coinspect/planning/path_smoothing.h"

#include <limits>

namespace coinspect::planning {

double pathLength(const std::vector<Vec3>& path) {
  double length = 0.0;
  for (size_t i = 1; i < path.size(); ++i)
    length += (path[i] - path[i - 1]).norm();
  return length;
}

std::vector<Vec3> shortcutPath(const VoxelGrid& grid, const std::vector<Vec3>& path,
                               const PathSearchOptions& options) {
  if (path.size() <= 2) return path;
  constexpr double kInf = std::numeric_limits<double>::infinity();
  // Weighted cost of each input edge; an edge that fails the check counts as infinitely
  // expensive, so no shortcut over it is rejected for cost reasons.
  std::vector<double> edgeCost(path.size() - 1);
  for (size_t i = 0; i + 1 < path.size(); ++i) {
    double cost = 0.0;
    edgeCost[i] = segmentTraversable(grid, path[i], path[i + 1], options, &cost) ? cost : kInf;
  }
  std::vector<Vec3> out{path.front()};
  size_t anchor = 0;
  while (anchor + 1 < path.size()) {
    size_t reach = anchor + 1;
    double replaced = edgeCost[anchor];
    for (size_t j = anchor + 2; j < path.size(); ++j) {
      replaced += edgeCost[j - 1];
      double cost = 0.0;
      if (!segmentTraversable(grid, path[anchor], path[j], options, &cost)) break;
      if (cost > replaced + 1e-9 * (1.0 + replaced)) break;
      reach = j;
    }
    out.push_back(path[reach]);
    anchor = reach;
  }
  return out;
}

}  // namespace coinspect::planning
