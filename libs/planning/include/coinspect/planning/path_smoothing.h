// Shortcutting of grid paths: drops vertices while the straight replacement is traversable under
// the search's rule (segmentTraversable: every touched cell traversable, with clearance) and
// costs no more than the stretch it replaces, so smoothing never cuts through a soft-clearance
// or unknown-cost zone that the search avoided. The endpoints are kept.
#pragma once

#include <vector>

#include "coinspect/planning/path_search.h"

namespace coinspect::planning {

// Greedy string pulling: from each kept vertex, the farthest later vertex reachable by one
// allowed shortcut (scanning forward, stopping at the first that fails). An edge of the input is
// kept even when it fails the check (e.g. leaving a blocked start cell), so a collision-free
// input gives a collision-free output. O(vertices x segment length).
std::vector<Vec3> shortcutPath(const VoxelGrid& grid, const std::vector<Vec3>& path,
                               const PathSearchOptions& options);

// Length (m) of a polyline.
double pathLength(const std::vector<Vec3>& path);

}  // namespace coinspect::planning
