#include "coinspect/planning/detection_coverage.h"

#include <algorithm>
#include <cmath>

namespace coinspect::planning {

namespace {

bool safePosition(const mapping::VoxelGrid& grid, const Vec3& p,
                  const DetectionCoverageOptions& o) {
  if (p.z() < o.groundZ + o.minHeight) return false;
  const auto cell = grid.cellOf(p);
  if (grid.state(cell) != mapping::CellState::Free || grid.clearance(cell) < o.clearance)
    return false;
  return !o.reachable || (*o.reachable)[grid.linear(cell)] != 0;
}

// Places around a patch from which a level detector heading at it would see it: in front of a
// wall (straight and turned 0.6 rad either way; level, a little above and below), above a roof
// from all sides (inside the elevation band), below an underside. Nearest standoff first.
std::vector<Vec3> candidatePositions(const InspectionPatch& patch,
                                     const DetectionCoverageOptions& o) {
  const Vec3& n = patch.normal;
  // Rises up to nearly the band's edge: a UAV keeps its clearance above a roof only that high.
  const double lean = std::tan(0.95 * o.detector.halfElevation);
  std::vector<double> azimuths;
  if (std::hypot(n.x(), n.y()) > 0.5) {
    const double base = std::atan2(n.y(), n.x());
    azimuths = {base, base + 0.6, base - 0.6};
  } else {
    for (int k = 0; k < 8; ++k)
      azimuths.push_back(k * M_PI / 4.0);
  }
  std::vector<Vec3> out;
  // The foot of a wall, first: from the places below, beside or a little above a low patch a
  // UAV is within its clearance of the ground, or sees the patch's centre but not the strip
  // along the ground (out of the band from that near). From the lowest safe heights, and as far
  // out as the band needs to reach the ground (slei-c, scene seed 1: 31 of the 47 features never
  // detected were on the lowest 0.45 m of walls and plinths).
  if (std::abs(n.z()) <= 0.5)
    for (const double above : {0.1, 0.35}) {
      const double height = std::max(o.minHeight, o.clearance) + above;  // over the ground
      if (patch.centre.z() - o.groundZ >= height) break;  // not low: the places beside it do
      const double r = height / std::tan(o.detector.halfElevation);
      if (std::hypot(r, height) > o.detector.range) break;
      for (const double a : azimuths)
        out.push_back(Vec3(patch.centre.x() + r * std::cos(a), patch.centre.y() + r * std::sin(a),
                           o.groundZ + height));
    }
  for (const double r : o.standoffs) {
    std::vector<double> rises;
    if (n.z() > 0.5)
      rises = {r * lean, 0.5 * r * lean};
    else if (n.z() < -0.5)
      rises = {-r * lean, -0.5 * r * lean};
    else
      rises = {0.0, 0.6 * r * lean, -0.6 * r * lean};
    for (const double rise : rises) {
      if (std::hypot(r, rise) > o.detector.range) continue;
      for (const double a : azimuths)
        out.push_back(patch.centre + Vec3(r * std::cos(a), r * std::sin(a), rise));
    }
  }
  return out;
}

}  // namespace

bool detects(const DetectorModel& detector, const mapping::VoxelGrid& grid, const Vec3& position,
             double yaw, const InspectionPatch& patch, bool unknownHides) {
  const Vec3 v = patch.centre - position;
  const double distance = v.norm();
  if (distance > detector.range || distance < 1e-6) return false;
  const double horizontal = std::hypot(v.x(), v.y());
  if (std::abs(std::atan2(v.z(), horizontal)) > detector.halfElevation) return false;
  if (horizontal > 1e-9 &&
      std::abs(std::remainder(std::atan2(v.y(), v.x()) - yaw, 2.0 * M_PI)) > detector.halfYaw)
    return false;
  if (patch.normal.dot(-v) < detector.minFacing * distance) return false;
  return lineOfSight(grid, position, patchFace(grid, patch), unknownHides);
}

std::vector<DetectionView> detectionViews(const std::vector<InspectionPatch>& patches,
                                          const mapping::VoxelGrid& grid,
                                          const DetectionCoverageOptions& options,
                                          std::vector<uint32_t>* uncoverable) {
  struct Candidate {
    Vec3 position, target;
    double yaw;
  };
  std::vector<Candidate> candidates;
  std::vector<std::vector<uint32_t>> sees;
  const double reach2 = options.detector.range * options.detector.range;
  for (const auto& patch : patches) {
    size_t kept = 0;
    for (const Vec3& p : candidatePositions(patch, options)) {
      if (kept == options.candidatesPerPatch) break;
      const double yaw = std::atan2(patch.centre.y() - p.y(), patch.centre.x() - p.x());
      if (!safePosition(grid, p, options) ||
          !detects(options.detector, grid, p, yaw, patch, options.unknownHides))
        continue;
      ++kept;
      std::vector<uint32_t> seen;
      // All patches: the explorer plans over a few hundred at a time.
      for (uint32_t j = 0; j < patches.size(); ++j)
        if ((patches[j].centre - p).squaredNorm() <= reach2 &&
            detects(options.detector, grid, p, yaw, patches[j], options.unknownHides))
          seen.push_back(j);
      candidates.push_back({p, patch.centre, yaw});
      sees.push_back(std::move(seen));
    }
  }
  std::vector<DetectionView> out;
  std::vector<char> covered(patches.size(), 0);
  for (auto& [c, newly] : greedyCover(sees, patches)) {
    for (const uint32_t j : newly)
      covered[j] = 1;
    out.push_back(
        {candidates[c].position, candidates[c].yaw, candidates[c].target, std::move(newly)});
  }
  if (uncoverable) {
    uncoverable->clear();
    for (uint32_t i = 0; i < patches.size(); ++i)
      if (!covered[i]) uncoverable->push_back(i);
  }
  return out;
}

}  // namespace coinspect::planning
