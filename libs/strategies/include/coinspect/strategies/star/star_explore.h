// Team STAR's exploration (FUEL-style): frontier clusters of the own map near the boxes, for
// each one the viewpoint on rings around its centre that sees the most of its cells, and an
// asymmetric TSP over the viewpoints (travel plus heading change) from where the robot is; the
// robot flies to the first and plans again (receding horizon).
#pragma once

#include <optional>
#include <vector>

#include "coinspect/agent/observations.h"
#include "coinspect/mapping/occupancy_map.h"
#include "coinspect/mapping/voxel_grid.h"

namespace coinspect::strategies::star {

using agent::Vec3;

struct Pose {
  Vec3 position = Vec3::Zero();
  double yaw = 0.0;  // rad
};

struct RingOptions {
  std::vector<double> radii{4.0, 7.0, 10.0};    // m, horizontal distance from the cluster centre
  std::vector<double> heights{0.0, 3.0, -2.0};  // m above the cluster centre
  int perRing = 8;                              // candidates per ring
  double range = 25.0;                          // m: LiDAR range that counts as seeing a cell
  double clearance = 1.5;                       // m: required clearance of a candidate (grid)
  double minZ = -1e300;                         // m: candidates lower than this are dropped
  size_t maxCells = 40;                         // cells of a cluster sampled for the count
};

// The candidates, ring by ring (radii outer loop, then heights, then angles from +x ccw).
std::vector<Vec3> ringCandidates(const Vec3& centre, const RingOptions& options);

// How many of `cells` lie within `range` of `from` with a line of sight through known-free
// cells of the grid (the cells themselves are free: they are frontier cells).
size_t visibleCells(const mapping::VoxelGrid& grid, const Vec3& from,
                    const std::vector<Vec3>& cells, double range);

struct RingViewpoint {
  Pose pose;        // heading towards the cluster centre
  size_t seen = 0;  // sampled cells it sees
};

// The candidate with the required clearance in the grid that sees most of the cluster's
// (sampled) cells; ties to the earlier candidate. None when no candidate sees any cell.
std::optional<RingViewpoint> bestRingViewpoint(const mapping::FrontierCluster& cluster,
                                               const mapping::VoxelGrid& grid,
                                               const RingOptions& options);

// Visiting order (indices into `poses`) of an open asymmetric TSP from `start`: the cost of a
// leg is its length plus `yawWeight` times the heading change it needs.
std::vector<size_t> atspOrder(const Pose& start, const std::vector<Pose>& poses, double yawWeight);

// Absolute heading change (rad, [0, pi]) from a to b.
double yawChange(double a, double b);

}  // namespace coinspect::strategies::star
