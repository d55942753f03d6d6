#include "coinspect/strategies/kios/waypoints.h"

#include <algorithm>
#include <numeric>

#include "coinspect/planning/coverage.h"
#include "coinspect/planning/routing_mtsp.h"
#include "coinspect/strategies/runtime/box_geometry.h"

namespace coinspect::strategies::kios {

using mapping::CellState;
using mapping::Index3;

std::vector<mapping::SurfaceVoxel> viewCells(const mapping::VoxelGrid& grid,
                                             const std::vector<BoxView>& boxes, double boxMargin,
                                             double groundZ) {
  static const Index3 kFaces[6] = {{-1, 0, 0}, {1, 0, 0},  {0, -1, 0},
                                   {0, 1, 0},  {0, 0, -1}, {0, 0, 1}};
  // Boxes' bounds grown by the margin: a cheap test before the exact distance.
  std::vector<runtime::Aabb> bounds;
  for (const auto& box : boxes) {
    auto b = runtime::boxBounds(box);
    b.min -= Vec3::Constant(boxMargin + grid.resolution());
    b.max += Vec3::Constant(boxMargin + grid.resolution());
    bounds.push_back(b);
  }
  std::vector<mapping::SurfaceVoxel> out;
  const Index3 size = grid.size();
  for (int z = 0; z < size.z(); ++z)
    for (int y = 0; y < size.y(); ++y)
      for (int x = 0; x < size.x(); ++x) {
        const Index3 cell(x, y, z);
        if (grid.state(cell) != CellState::Free) continue;
        Vec3 view = Vec3::Zero();
        for (const auto& face : kFaces)
          if (grid.state(cell + face) == CellState::Occupied) view += face.cast<double>();
        // Occupied on opposite faces cancel: a free cell squeezed between surfaces has no view.
        if (view.squaredNorm() < 1e-9) continue;
        view.normalize();
        const Vec3 surface = grid.centre(cell) + 0.5 * grid.resolution() * view;
        if (planning::isGroundSurface({surface, -view}, groundZ, grid.resolution())) continue;
        bool nearBox = false;
        for (size_t b = 0; b < boxes.size() && !nearBox; ++b)
          nearBox =
              bounds[b].contains(surface) && runtime::distanceToBox(boxes[b], surface) <= boxMargin;
        if (nearBox) out.push_back({surface, -view});
      }
  return out;
}

std::vector<InspectionWaypoint> inspectionWaypoints(
    const mapping::VoxelGrid& grid, const std::vector<BoxView>& boxes,
    const WaypointOptions& options, const planning::PathSearchOptions& pathOptions) {
  planning::ViewpointOptions viewpoint = options.viewpoint;
  viewpoint.grid = &grid;
  viewpoint.pathOptions = pathOptions;
  std::vector<InspectionWaypoint> out;
  const auto patches = planning::groupSurface(
      viewCells(grid, boxes, options.boxMargin, options.groundZ), options.spacing);
  for (const auto& patch : patches) {
    const auto view = planning::makeViewpoint({patch.centre, patch.normal}, viewpoint);
    if (!view.free) continue;
    InspectionWaypoint waypoint;
    waypoint.id = patch.key;
    waypoint.body = view.body;
    waypoint.target = patch.centre;
    waypoint.yaw = view.bodyYaw;
    waypoint.view = (patch.centre - view.camera).normalized();
    out.push_back(waypoint);
  }
  std::sort(out.begin(), out.end(),
            [](const InspectionWaypoint& a, const InspectionWaypoint& b) { return a.id < b.id; });
  return out;
}

std::vector<std::vector<size_t>> assignWaypoints(const std::vector<Vec3>& vehicles,
                                                 const std::vector<InspectionWaypoint>& waypoints,
                                                 const AssignmentOptions& options) {
  std::vector<std::vector<size_t>> out(vehicles.size());
  if (vehicles.empty() || waypoints.empty()) return out;
  std::vector<size_t> byId(waypoints.size());
  std::iota(byId.begin(), byId.end(), size_t{0});
  std::stable_sort(byId.begin(), byId.end(),
                   [&](size_t a, size_t b) { return waypoints[a].id < waypoints[b].id; });
  std::vector<Eigen::Vector3d> points(vehicles.begin(), vehicles.end());
  for (const size_t i : byId)
    points.push_back(waypoints[i].body);
  planning::MtspProblem problem;
  for (size_t v = 0; v < vehicles.size(); ++v)
    problem.starts.push_back(static_cast<int>(v));
  problem.objective = planning::MtspObjective::MinMax;
  planning::LocalSearchOptions search;
  search.maxEvaluations = options.maxEvaluations;
  search.kicks = options.kicks;
  search.seed = options.seed;
  const auto solution = planning::solveMtsp(planning::euclideanCostMatrix(points), problem, search);
  for (size_t v = 0; v < vehicles.size(); ++v)
    for (size_t k = 1; k < solution.routes[v].size(); ++k)
      out[v].push_back(byId[static_cast<size_t>(solution.routes[v][k]) - vehicles.size()]);
  return out;
}

}  // namespace coinspect::strategies::kios
