// SampleLOS: meeting points around a hover pose (see meeting_sampling.h).
#include "coinspect/planning/meeting_sampling.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "coinspect/core/error.h"

namespace coinspect::planning {

namespace {

using mapping::CellState;
using mapping::Index3;

bool freeWithClearance(const VoxelGrid& grid, const Index3& cell, double clearance) {
  if (grid.state(cell) != CellState::Free) return false;
  return clearance <= 0.0 || grid.clearance(cell) >= clearance;
}

// Every cell the segment [from, to] passes through, in order (a 3-D DDA: from one cell boundary
// crossing to the next), must be free with the clearance.
bool segmentFree(const VoxelGrid& grid, const Vec3& from, const Vec3& to, double clearance) {
  Index3 cell = grid.cellOf(from);
  const Index3 last = grid.cellOf(to);
  if (!freeWithClearance(grid, cell, clearance) || !freeWithClearance(grid, last, clearance))
    return false;
  const Vec3 delta = to - from;
  const double resolution = grid.resolution();
  const double infinity = std::numeric_limits<double>::infinity();
  Index3 step = Index3::Zero();
  Vec3 nextCrossing = Vec3::Constant(infinity);  // segment parameter of the next boundary
  Vec3 crossingGap = Vec3::Constant(infinity);   // parameter between two boundaries
  for (int axis = 0; axis < 3; ++axis) {
    if (delta[axis] == 0.0) continue;
    step[axis] = delta[axis] > 0.0 ? 1 : -1;
    const double boundary =
        grid.origin()[axis] + (cell[axis] + (delta[axis] > 0.0 ? 1 : 0)) * resolution;
    nextCrossing[axis] = (boundary - from[axis]) / delta[axis];
    crossingGap[axis] = resolution / std::abs(delta[axis]);
  }
  // One crossing per cell of difference; rounding can only end the walk early, and the last
  // cell was checked above.
  const int crossings = (last - cell).cwiseAbs().sum();
  for (int i = 0; i < crossings; ++i) {
    int axis = 0;
    if (nextCrossing[1] < nextCrossing[axis]) axis = 1;
    if (nextCrossing[2] < nextCrossing[axis]) axis = 2;
    if (nextCrossing[axis] > 1.0) break;
    cell[axis] += step[axis];
    nextCrossing[axis] += crossingGap[axis];
    if (!freeWithClearance(grid, cell, clearance)) return false;
  }
  return true;
}

}  // namespace

MeetingSpace voxelGridMeetingSpace(const VoxelGrid& grid, double freeClearance,
                                   double sightClearance) {
  if ((freeClearance > 0.0 || sightClearance > 0.0) && !grid.hasClearance()) {
    throw InputError("meeting space", "clearance",
                     "a positive clearance needs the grid's clearance field");
  }
  MeetingSpace space;
  space.isFree = [&grid, freeClearance](const Vec3& point) {
    return freeWithClearance(grid, grid.cellOf(point), freeClearance);
  };
  space.lineOfSight = [&grid, sightClearance](const Vec3& from, const Vec3& to) {
    return segmentFree(grid, from, to, sightClearance);
  };
  return space;
}

void validateMeetingSampling(const MeetingSamplingOptions& options) {
  const char* const source = "meeting sampling options";
  if (!(options.step > 0.0))
    throw InputError(source, "step", std::to_string(options.step) + " is not positive");
  if (!(options.communicationRange > 0.0)) {
    throw InputError(source, "communicationRange",
                     std::to_string(options.communicationRange) + " is not positive");
  }
  if (!(options.rangeMargin >= 0.0)) {
    throw InputError(source, "rangeMargin", std::to_string(options.rangeMargin) + " is negative");
  }
  if (!(options.minSeparation >= 0.0)) {
    throw InputError(source, "minSeparation",
                     std::to_string(options.minSeparation) + " is negative");
  }
  if (!(options.partnerRadius >= 0.0)) {
    throw InputError(source, "partnerRadius",
                     std::to_string(options.partnerRadius) + " is negative");
  }
  if (options.maxSamples < 1) {
    throw InputError(source, "maxSamples", std::to_string(options.maxSamples) + " is below 1");
  }
}

std::vector<Vec3> sampleMeetingPoints(const Vec3& pose, const MeetingBox& box,
                                      const MeetingSpace& space,
                                      const MeetingSamplingOptions& options) {
  validateMeetingSampling(options);
  std::vector<Vec3> kept;
  const double reach = options.communicationRange - options.rangeMargin;
  if (reach < options.minSeparation) return kept;
  // Nodes beyond `reach` along an axis are out of the ball anyway: no need to scan the full
  // +-range cube of the reference. The small slack keeps a node lying exactly at `reach`.
  const double slack = 1e-9;
  const int half = static_cast<int>(std::floor(reach / options.step + slack));
  for (int i = -half; i <= half; ++i) {
    for (int j = -half; j <= half; ++j) {
      for (int k = -half; k <= half; ++k) {
        const Vec3 offset = Vec3(i, j, k) * options.step;
        const double distance = offset.norm();
        if (distance > reach + slack || distance < options.minSeparation - slack) continue;
        const Vec3 node = pose + offset;
        if (!box.contains(node)) continue;
        const Vec3 seen = pose + offset * std::min(1.0, options.partnerRadius / distance);
        if (!space.isFree(node) || !space.lineOfSight(node, seen)) continue;
        kept.push_back(node);
      }
    }
  }
  const size_t cap = static_cast<size_t>(options.maxSamples);
  if (kept.size() <= cap) return kept;
  std::vector<Vec3> thinned;
  thinned.reserve(cap);
  for (size_t i = 0; i < cap; ++i)
    thinned.push_back(kept[i * kept.size() / cap]);
  return thinned;
}

}  // namespace coinspect::planning
