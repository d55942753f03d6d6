// Candidate meeting points around an inspector's hover pose (SLEI3D's "SampleLOS").
//
// An explorer that wants to hand features to an inspector has to come within communication range
// of it with a clear line of sight. The inspector's plan is a list of hover poses, so the
// candidates are the nodes of a regular grid around each pose that a link would reach: within
// (range - margin) of the pose, inside the explorer's box, free with clearance, and in line of
// sight of the pose. The map is taken as two queries (MeetingSpace), so the sampling can be
// tested without a real map; voxelGridMeetingSpace builds them from a VoxelGrid.
#pragma once

#include <functional>
#include <vector>

#include "coinspect/mapping/voxel_grid.h"

namespace coinspect::planning {

using mapping::Vec3;
using mapping::VoxelGrid;

// An axis-aligned region, given by its minimum and maximum corners (the explorer's box).
struct MeetingBox {
  Vec3 min = Vec3::Zero();
  Vec3 max = Vec3::Zero();

  bool contains(const Vec3& point) const {
    return (point.array() >= min.array()).all() && (point.array() <= max.array()).all();
  }
};

// The map as seen by the sampling: where the explorer may hold, and which segments a link sees
// through.
struct MeetingSpace {
  std::function<bool(const Vec3&)> isFree;
  std::function<bool(const Vec3& from, const Vec3& to)> lineOfSight;
};

// Queries on `grid`, which must outlive the returned space:
//   isFree(p)          = p's cell is known Free and its clearance >= freeClearance;
//   lineOfSight(a, b)  = every cell the segment [a, b] passes through (an exact voxel walk,
//                        which also catches the corners that sampling every half cell can step
//                        over) is known Free, with clearance >= sightClearance: occupied and
//                        unknown cells block, and so does everything outside the grid.
// A positive clearance needs grid.computeClearance() first (throws InputError otherwise).
MeetingSpace voxelGridMeetingSpace(const VoxelGrid& grid, double freeClearance,
                                   double sightClearance = 0.0);

struct MeetingSamplingOptions {
  double communicationRange = 5.0;  // m, the link's range
  double rangeMargin = 1.0;         // m; samples lie within (range - margin) of the pose
  // m; samples closer than this to the pose are dropped, so that the explorer does not fly into
  // the hovering inspector (not in the reference, which would even use the pose itself)
  double minSeparation = 1.0;
  // m around the pose that only the partner itself can fill: the line of sight is checked from a
  // node to the point this far from the pose towards it. A robot's map shows a UAV it has no link
  // with as an obstacle (its scan points are dropped only for neighbours), so an inspector
  // hovering at its pose blocked every sight line to it (0: to the pose itself, the reference).
  double partnerRadius = 0.0;
  double step = 0.4;      // m, grid spacing (the reference's 0.2 m voxels / density 0.5)
  int maxSamples = 1000;  // per pose; more are thinned uniformly by index
};

// Throws InputError (source "meeting sampling options") for a non-positive step, range or sample
// cap, a negative margin or separation.
void validateMeetingSampling(const MeetingSamplingOptions& options);

// The grid nodes pose + step (i, j, k), scanned with x slowest and z fastest, kept when
// minSeparation <= |offset| <= range - margin, box.contains(node), space.isFree(node) and
// space.lineOfSight(node, pose + offset * min(1, partnerRadius / |offset|)); then, when more than
// maxSamples remain, the ones at indices floor(i n / maxSamples) for i = 0 .. maxSamples - 1.
// Deterministic; the queries are asked in that order, cheapest filters first.
std::vector<Vec3> sampleMeetingPoints(const Vec3& pose, const MeetingBox& box,
                                      const MeetingSpace& space,
                                      const MeetingSamplingOptions& options);

}  // namespace coinspect::planning
