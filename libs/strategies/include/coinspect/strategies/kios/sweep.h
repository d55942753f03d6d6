// `kios` exploration: the operational volume (every box's bounds) is cut into one slab per
// explorer across its longest horizontal axis, and each explorer sweeps its slab in lawnmower
// passes along that axis: one pass on each long side of the volume per height, outside it at a
// standoff (the LiDAR reaches 50 m, so the structure stays in range), then passes above the top.
// Every explorer computes the same slabs from the same boxes and the fleet roster, so the split
// needs no message.
#pragma once

#include <vector>

#include "coinspect/strategies/runtime/box_geometry.h"

namespace coinspect::strategies::kios {

using runtime::Aabb;
using runtime::Vec3;

// 0 (x) or 1 (y): the longer horizontal side of `volume`; ties go to x.
int longHorizontalAxis(const Aabb& volume);

// `parts` (>= 1) equal slabs of `volume` in order along its long horizontal axis; every slab
// keeps the volume's extent across that axis and in height.
std::vector<Aabb> splitSlabs(const Aabb& volume, size_t parts);

struct SweepOptions {
  double standoff = 10.0;       // m outside the volume's long sides for the side passes
  double laneSpacing = 40.0;    // m at most between passes above the top (across the long axis)
  double topClearance = 5.0;    // m above the volume's top for the passes above it
  double spacing = 5.0;         // m between waypoints along a pass
  std::vector<double> heights;  // world z of the side passes, bottom to top
};

// The lawnmower route over `slab` (a part of `volume`, same long axis): for each height, a pass
// along the long axis beside one long side of the volume and back beside the other; then passes
// above the top across the volume's width, alternating directions. Of the four mirror images
// (start at either end, on either side) the one starting nearest `near` is returned (ties: the
// first of long-end-low/side-low, long-high/side-low, long-low/side-high, long-high/side-high).
std::vector<Vec3> lawnmowerSweep(const Aabb& volume, const Aabb& slab, const SweepOptions& options,
                                 const Vec3& near);

}  // namespace coinspect::strategies::kios
