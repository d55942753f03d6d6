#include "coinspect/planning/coverage.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <queue>
#include <tuple>

namespace coinspect::planning {

namespace {

using mapping::CellState;
using mapping::Index3;

// The dominant signed axis of a normal, 0..5 (+x, -x, +y, -y, +z, -z).
int dominantAxis(const Vec3& normal) {
  int axis = 0;
  normal.cwiseAbs().maxCoeff(&axis);
  return 2 * axis + (normal[axis] < 0.0 ? 1 : 0);
}

bool safeCamera(const mapping::VoxelGrid& grid, const Vec3& camera, const CoverageOptions& o) {
  if (camera.z() < o.groundZ + o.minHeight) return false;
  const Index3 cell = grid.cellOf(camera);
  return grid.state(cell) == CellState::Free && grid.clearance(cell) >= o.clearance;
}

// A safe camera position for a patch: along its normal at the preferred distance, else closer,
// else lifted (a downward-facing patch near the ground is seen from the side).
bool placeCamera(const mapping::VoxelGrid& grid, const InspectionPatch& patch,
                 const CoverageOptions& o, Vec3* camera) {
  const Vec3 up = Vec3::UnitZ();
  Vec3 lifted = patch.normal + 0.7 * up;
  lifted.normalize();
  for (const Vec3& direction : {patch.normal, lifted})
    for (const double scale : {1.0, 0.85, 0.7, 1.15}) {
      const Vec3 candidate = patch.centre + scale * o.distance * direction;
      if (safeCamera(grid, candidate, o) &&
          lineOfSight(grid, candidate, patchFace(grid, patch), o.unknownHides)) {
        *camera = candidate;
        return true;
      }
    }
  return false;
}

bool covers(const mapping::VoxelGrid& grid, const Vec3& camera, const Vec3& axis,
            const InspectionPatch& patch, const CoverageOptions& o) {
  const Vec3 toCamera = camera - patch.centre;
  const double distance = toCamera.norm();
  if (distance > o.maxDistance || distance < 1e-6) return false;
  if (patch.normal.dot(toCamera) < std::cos(o.maxIncidence) * distance) return false;
  if (axis.dot(-toCamera) < std::cos(o.halfFov) * distance) return false;
  return lineOfSight(grid, camera, patchFace(grid, patch), o.unknownHides);
}

}  // namespace

Vec3 patchFace(const mapping::VoxelGrid& grid, const InspectionPatch& patch) {
  return patch.centre + 0.55 * grid.resolution() * patch.normal;
}

bool isGroundSurface(const mapping::SurfaceVoxel& voxel, double groundZ, double resolution) {
  return voxel.normal.z() > 0.8 && voxel.centre.z() <= groundZ + 1.25 * resolution;
}

std::vector<InspectionPatch> groupSurface(const std::vector<mapping::SurfaceVoxel>& voxels,
                                          double patchSize) {
  struct Sum {
    Vec3 centre = Vec3::Zero(), normal = Vec3::Zero();
    uint32_t count = 0;
  };
  std::map<std::tuple<int, int, int, int>, Sum> bins;  // ordered: deterministic output
  for (const auto& voxel : voxels) {
    const Vec3 scaled = voxel.centre / patchSize;
    auto& sum =
        bins[{static_cast<int>(std::floor(scaled.x())), static_cast<int>(std::floor(scaled.y())),
              static_cast<int>(std::floor(scaled.z())), dominantAxis(voxel.normal)}];
    sum.centre += voxel.centre;
    sum.normal += voxel.normal;
    ++sum.count;
  }
  std::vector<InspectionPatch> out;
  out.reserve(bins.size());
  for (const auto& [key, sum] : bins) {
    InspectionPatch patch;
    // 20 bits per coordinate (offset to stay positive) and 3 for the axis.
    const auto field = [](int value) { return static_cast<uint64_t>(value + (1 << 19)) & 0xFFFFF; };
    patch.key = (field(std::get<0>(key)) << 43) | (field(std::get<1>(key)) << 23) |
                (field(std::get<2>(key)) << 3) | static_cast<uint64_t>(std::get<3>(key));
    patch.centre = sum.centre / sum.count;
    patch.normal = sum.normal.norm() > 1e-9 ? Vec3(sum.normal.normalized()) : Vec3(Vec3::UnitZ());
    patch.weight = sum.count;
    out.push_back(patch);
  }
  return out;
}

bool freeLineOfSight(const mapping::VoxelGrid& grid, const Vec3& a, const Vec3& b) {
  return lineOfSight(grid, a, b, true);
}

bool lineOfSight(const mapping::VoxelGrid& grid, const Vec3& a, const Vec3& b, bool unknownBlocks) {
  // Amanatides-Woo traversal; the cells holding `b` itself and the cell of `a` are not
  // required to be free (b is usually a surface point inside an occupied voxel).
  const double resolution = grid.resolution();
  Index3 cell = grid.cellOf(a);
  const Index3 last = grid.cellOf(b);
  const Vec3 direction = b - a;
  Vec3 tMax, tDelta;
  Index3 stepDir;
  for (int i = 0; i < 3; ++i) {
    if (std::abs(direction[i]) < 1e-12) {
      stepDir[i] = 0;
      tMax[i] = tDelta[i] = std::numeric_limits<double>::infinity();
      continue;
    }
    stepDir[i] = direction[i] > 0 ? 1 : -1;
    const double boundary = grid.origin()[i] + (cell[i] + (stepDir[i] > 0 ? 1 : 0)) * resolution;
    tMax[i] = (boundary - a[i]) / direction[i];
    tDelta[i] = resolution / std::abs(direction[i]);
  }
  while (cell != last) {
    int axis = 0;
    tMax.minCoeff(&axis);
    if (tMax[axis] > 1.0) break;
    cell[axis] += stepDir[axis];
    tMax[axis] += tDelta[axis];
    if (cell == last) break;
    const CellState state = grid.state(cell);
    if (state == CellState::Occupied || (unknownBlocks && state == CellState::Unknown))
      return false;
  }
  return true;
}

std::vector<std::pair<uint32_t, std::vector<uint32_t>>> greedyCover(
    const std::vector<std::vector<uint32_t>>& sees, const std::vector<InspectionPatch>& patches) {
  // Lazy greedy set cover, weighted by patch weight; ties go to the lower candidate index.
  std::vector<char> covered(patches.size(), 0);
  const auto gain = [&](const std::vector<uint32_t>& seen) {
    uint64_t total = 0;
    for (const uint32_t j : seen)
      if (!covered[j]) total += patches[j].weight;
    return total;
  };
  using Entry = std::pair<uint64_t, uint32_t>;  // (gain, -index) ordering below
  const auto worse = [](const Entry& a, const Entry& b) {
    return a.first != b.first ? a.first < b.first : a.second > b.second;
  };
  std::priority_queue<Entry, std::vector<Entry>, decltype(worse)> queue(worse);
  for (uint32_t c = 0; c < sees.size(); ++c)
    queue.push({gain(sees[c]), c});
  std::vector<std::pair<uint32_t, std::vector<uint32_t>>> out;
  while (!queue.empty()) {
    const auto [stale, c] = queue.top();
    queue.pop();
    const uint64_t fresh = gain(sees[c]);
    if (fresh == 0) continue;
    if (fresh < stale) {
      queue.push({fresh, c});
      continue;
    }
    std::vector<uint32_t> newly;
    for (const uint32_t j : sees[c])
      if (!covered[j]) {
        covered[j] = 1;
        newly.push_back(j);
      }
    out.emplace_back(c, std::move(newly));
  }
  return out;
}

std::vector<CoverageView> coverPatches(const std::vector<InspectionPatch>& patches,
                                       const mapping::VoxelGrid& grid,
                                       const CoverageOptions& options,
                                       std::vector<uint32_t>* uncoverable) {
  const size_t n = patches.size();
  // Candidate viewpoints: one per patch, looking at it.
  struct Candidate {
    Vec3 camera, target;
    std::vector<uint32_t> sees;
  };
  std::vector<Candidate> candidates;
  candidates.reserve(n);
  // Spatial hash of patch centres for the neighbour search.
  const double cellSize = options.maxDistance;
  std::map<std::tuple<int, int, int>, std::vector<uint32_t>> buckets;
  const auto bucketOf = [&](const Vec3& p) {
    return std::make_tuple(static_cast<int>(std::floor(p.x() / cellSize)),
                           static_cast<int>(std::floor(p.y() / cellSize)),
                           static_cast<int>(std::floor(p.z() / cellSize)));
  };
  for (uint32_t i = 0; i < n; ++i)
    buckets[bucketOf(patches[i].centre)].push_back(i);
  for (uint32_t i = 0; i < n; ++i) {
    Candidate candidate;
    if (!placeCamera(grid, patches[i], options, &candidate.camera)) continue;
    candidate.target = patches[i].centre;
    const Vec3 axis = (candidate.target - candidate.camera).normalized();
    const auto [bx, by, bz] = bucketOf(candidate.camera);
    for (int dz = -1; dz <= 1; ++dz)
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
          const auto found = buckets.find({bx + dx, by + dy, bz + dz});
          if (found == buckets.end()) continue;
          for (const uint32_t j : found->second)
            if (covers(grid, candidate.camera, axis, patches[j], options))
              candidate.sees.push_back(j);
        }
    std::sort(candidate.sees.begin(), candidate.sees.end());
    if (!candidate.sees.empty()) candidates.push_back(std::move(candidate));
  }

  std::vector<std::vector<uint32_t>> sees;
  sees.reserve(candidates.size());
  for (const auto& candidate : candidates)
    sees.push_back(candidate.sees);
  std::vector<CoverageView> out;
  std::vector<char> covered(n, 0);
  for (auto& [c, newly] : greedyCover(sees, patches)) {
    for (const uint32_t j : newly)
      covered[j] = 1;
    out.push_back({candidates[c].camera, candidates[c].target, std::move(newly)});
  }
  if (uncoverable) {
    uncoverable->clear();
    for (uint32_t i = 0; i < n; ++i)
      if (!covered[i]) uncoverable->push_back(i);
  }
  return out;
}

}  // namespace coinspect::planning
