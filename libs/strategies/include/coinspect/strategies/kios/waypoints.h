// `kios` inspection planning on the voxel graph (the robot's planning grid):
// - inspection waypoints: the free cells next to occupied ones near a box, each with a view
//   direction toward its occupied neighbours; grouped into bins of `spacing` (stable keys while
//   the map grows, so visited waypoints are remembered by id), each bin seen from the camera
//   position at the q_res = 1 distance along its outward normal (planning::makeViewpoint);
// - a min-max mTSP over the photographers and the waypoints, solved from sorted inputs with a
//   fixed seed, so every photographer that knows the same gets the same assignment and flies its
//   own share without messages.
#pragma once

#include <cstdint>
#include <limits>
#include <vector>

#include "coinspect/agent/observations.h"
#include "coinspect/mapping/occupancy_map.h"
#include "coinspect/mapping/voxel_grid.h"
#include "coinspect/planning/viewpoint.h"

namespace coinspect::strategies::kios {

using agent::BoxView;
using agent::Vec3;

// Free cells of `grid` with at least one occupied face neighbour, as surface samples: the centre
// is the face shared with the occupied neighbours (averaged), the normal points out of the
// surface, i.e. opposite to the view direction (the sum of the unit offsets to the occupied
// neighbours). Only samples within `boxMargin` of a box count (interest points lie in boxes),
// and none of the ground at `groundZ` (planning::isGroundSurface). Grid order (z, y, x), so the
// result is deterministic.
std::vector<mapping::SurfaceVoxel> viewCells(
    const mapping::VoxelGrid& grid, const std::vector<BoxView>& boxes, double boxMargin,
    double groundZ = -std::numeric_limits<double>::infinity());

struct InspectionWaypoint {
  uint64_t id = 0;             // the bin's key (planning::InspectionPatch::key)
  Vec3 body = Vec3::Zero();    // where the body holds
  Vec3 target = Vec3::Zero();  // the surface point to look at
  double yaw = 0.0;            // body heading that faces it
  Vec3 view = Vec3::UnitX();   // unit view direction (toward the surface)
};

struct WaypointOptions {
  double spacing = 4.0;    // m, bin size of the surface samples
  double boxMargin = 1.0;  // m, samples farther from every box are dropped
  double groundZ = -std::numeric_limits<double>::infinity();  // m, its surface is dropped
  // Camera model, distance, limits; `grid` and `pathOptions` are filled from the call.
  planning::ViewpointOptions viewpoint;
};

// One waypoint per bin whose viewpoint has a traversable body position (`pathOptions` decide,
// e.g. the clearance the robot needs), sorted by id.
std::vector<InspectionWaypoint> inspectionWaypoints(const mapping::VoxelGrid& grid,
                                                    const std::vector<BoxView>& boxes,
                                                    const WaypointOptions& options,
                                                    const planning::PathSearchOptions& pathOptions);

struct AssignmentOptions {
  int64_t maxEvaluations = 200000;  // local-search budget (deterministic: counts moves)
  int kicks = 2;                    // iterated local search restarts
  uint64_t seed = 1;                // the same in every robot
};

// Min-max open mTSP on straight-line distances: vehicle v starts at vehicles[v]; the result
// holds, per vehicle, indices into `waypoints` in visiting order. The waypoints are ordered by
// id before solving, so the answer does not depend on their order in the input.
std::vector<std::vector<size_t>> assignWaypoints(const std::vector<Vec3>& vehicles,
                                                 const std::vector<InspectionWaypoint>& waypoints,
                                                 const AssignmentOptions& options);

}  // namespace coinspect::strategies::kios
