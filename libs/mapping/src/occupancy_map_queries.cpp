// OccupancyMap queries: clearance, dense snapshots, frontier clusters, surface voxels.
//
// The dense snapshots read the blocks that hold the region asked for (src/cell_blocks.h); the
// clearance skips blocks without an occupied cell or farther than the best distance so far.
#include <algorithm>
#include <array>
#include <cmath>
#include <map>

#include "cell_blocks.h"
#include "coinspect/core/error.h"
#include "coinspect/mapping/occupancy_map.h"

namespace coinspect::mapping {

namespace {

using Key3 = Eigen::Array3i;  // cell keys (0..65535 per axis)

// Calls visit(block) for every block holding cells of keys [low, high] (and maybe others: when
// the range spans more blocks than the map has, every block).
template <class Visit>
void forEachBlockIn(const CellBlocks& cells, const Key3& low, const Key3& high, Visit&& visit) {
  if ((low > high).any()) return;
  const Key3 firstBlock = low / CellBlocks::kBlockSide, lastBlock = high / CellBlocks::kBlockSide;
  if ((lastBlock - firstBlock + 1).cast<double>().prod() >
      static_cast<double>(cells.blocks().size())) {
    for (const auto& block : cells.blocks())
      visit(*block);
    return;
  }
  for (int z = firstBlock.z(); z <= lastBlock.z(); ++z)
    for (int y = firstBlock.y(); y <= lastBlock.y(); ++y)
      for (int x = firstBlock.x(); x <= lastBlock.x(); ++x) {
        const CellKey first{static_cast<uint16_t>(x * CellBlocks::kBlockSide),
                            static_cast<uint16_t>(y * CellBlocks::kBlockSide),
                            static_cast<uint16_t>(z * CellBlocks::kBlockSide)};
        if (const CellBlocks::Block* block = cells.blockOf(mortonOf(first))) visit(*block);
      }
}

// Calls visit(key, logOdds) for every known cell of keys [low, high].
template <class Visit>
void forEachKnownCellIn(const CellBlocks& cells, const Key3& low, const Key3& high, Visit&& visit) {
  forEachBlockIn(cells, low, high, [&](const CellBlocks::Block& block) {
    if (block.known == 0) return;
    const Key3 first(block.low[0], block.low[1], block.low[2]);
    const bool whole = (first >= low).all() && (first + (CellBlocks::kBlockSide - 1) <= high).all();
    for (unsigned i = 0; i < CellBlocks::kBlockCells; ++i) {
      const float value = block.logOdds[i];
      if (value == CellBlocks::kUnknown) continue;
      const auto& offset = CellBlocks::cellOffset(i);
      const Key3 k = first + Key3(offset[0], offset[1], offset[2]);
      if (whole || ((k >= low).all() && (k <= high).all())) visit(k, value);
    }
  });
}

// The key range (clamped to the keys) of the cells whose box reaches into [min, max] widened by
// `margin` cells each side.
void keyRange(const CellFrame& f, const Vec3& min, const Vec3& max, int margin, Key3& low,
              Key3& high) {
  for (int a = 0; a < 3; ++a) {
    const double lo = std::floor(min[a] * f.factor) + CellFrame::kKeyZero - margin;
    const double hi = std::floor(max[a] * f.factor) + CellFrame::kKeyZero + margin;
    low[a] = static_cast<int>(std::clamp(lo, 0.0, 65535.0));
    high[a] = static_cast<int>(std::clamp(hi, 0.0, 65535.0));
  }
}

// The minimum corner of a cell: (key - 32768) x resolution, per axis.
inline double cornerOf(const CellFrame& f, int key) {
  return static_cast<double>(key - CellFrame::kKeyZero) * f.resolution;
}

// The centre of a cell as the queries compute it: its corner plus half a cell (not
// CellFrame::centreOf's arithmetic, which may differ in the last bit; these are the expressions
// the tree's queries used, so that the grids and distances stay bit for bit what they were).
inline Vec3 queryCentre(const CellFrame& f, const CellKey& key) {
  return Vec3(cornerOf(f, key[0]), cornerOf(f, key[1]), cornerOf(f, key[2])) +
         Vec3::Constant(0.5 * f.resolution);
}

// Fills `part`, the cells [from, from + part size) of a grid of frame `whole`: a dense cell is
// Occupied if a map cell inside it is, else Free if one is known. A map cell no larger than a
// dense cell is placed by its centre, a larger one fills the dense cells whose centres it holds.
// Cells are found in the whole grid's frame, so that a cell reads the same in a part as in the
// whole grid. A map cell's dense cell depends on each key component alone, so it is tabulated
// per key value of the range (as many entries as the part is cells long) instead of computed
// per cell.
void fillGrid(const CellBlocks& cells, const GridFrame& whole, const Index3& from,
              VoxelGrid& part) {
  const CellFrame& f = cells.frame();
  const Index3 to = from + part.size() - Index3::Ones();
  const Vec3 partMin = whole.origin + from.cast<double>() * whole.resolution;
  const Vec3 partMax = whole.origin + (to + Index3::Ones()).cast<double>() * whole.resolution;
  const auto combine = [&](const Index3& wholeCell, CellState state) {
    const size_t index = part.linear(wholeCell - from);
    if (state == CellState::Occupied || part.stateAt(index) == CellState::Unknown)
      part.setAt(index, state);
  };
  Key3 low, high;
  keyRange(f, partMin, partMax, 1, low, high);
  if (f.resolution > whole.resolution * (1.0 + 1e-9)) {
    // Map cells larger than dense cells: every dense cell whose centre the map cell holds.
    forEachKnownCellIn(cells, low, high, [&](const Key3& k, float value) {
      const CellState state = f.occupied(value) ? CellState::Occupied : CellState::Free;
      const Vec3 lo(cornerOf(f, k[0]), cornerOf(f, k[1]), cornerOf(f, k[2]));
      const Vec3 hi = lo + Vec3::Constant(f.resolution);
      const Index3 first = whole.cellOf(lo).cwiseMax(from);
      const Index3 last = whole.cellOf(hi).cwiseMin(to);
      for (int z = first.z(); z <= last.z(); ++z)
        for (int y = first.y(); y <= last.y(); ++y)
          for (int x = first.x(); x <= last.x(); ++x) {
            const Index3 cell(x, y, z);
            const Vec3 c = whole.centre(cell);
            if ((c.array() >= lo.array()).all() && (c.array() < hi.array()).all())
              combine(cell, state);
          }
    });
    return;
  }
  // A grid of the map's resolution x 2, 4 or 8 whose cells are aligned with the map's: each of its
  // cells holds 8^k map cells that are consecutive in their block (the low 3k bits of their
  // in-block Morton code), so the block is read group by group, one dense cell per group.
  const double ratio = whole.resolution / f.resolution;
  const int k = static_cast<int>(std::lround(std::log2(ratio)));
  const Vec3 steps = whole.origin / whole.resolution;
  if (k >= 1 && k <= CellBlocks::kBlockBits &&
      std::abs(ratio - std::ldexp(1.0, k)) < 1e-9 * ratio &&
      ((steps.array() - steps.array().round()).abs() < 1e-6).all()) {
    const unsigned group = 1U << (3 * k);
    forEachBlockIn(cells, low, high, [&](const CellBlocks::Block& block) {
      if (block.known == 0) return;
      for (unsigned first = 0; first < CellBlocks::kBlockCells; first += group) {
        bool known = false, occupied = false;
        for (unsigned i = first; i < first + group; ++i) {
          const float value = block.logOdds[i];
          if (value == CellBlocks::kUnknown) continue;
          known = true;
          if (f.occupied(value)) {
            occupied = true;
            break;
          }
        }
        if (!known) continue;
        const CellKey key = CellBlocks::keyInBlock(block, first);
        const Index3 cell = whole.cellOf(queryCentre(f, key));
        if ((cell.array() < from.array()).any() || (cell.array() > to.array()).any()) continue;
        combine(cell, occupied ? CellState::Occupied : CellState::Free);
      }
    });
    return;
  }
  std::array<std::vector<int>, 3> cellOfKey;  // per axis, per key from low: the dense cell
  for (int a = 0; a < 3; ++a) {
    cellOfKey[a].resize(static_cast<size_t>(high[a] - low[a] + 1));
    for (int key = low[a]; key <= high[a]; ++key) {
      const Vec3 centre = Vec3::Constant(cornerOf(f, key) + 0.5 * f.resolution);
      cellOfKey[a][key - low[a]] = whole.cellOf(centre)[a];
    }
  }
  forEachKnownCellIn(cells, low, high, [&](const Key3& k, float value) {
    const Index3 cell(cellOfKey[0][k[0] - low[0]], cellOfKey[1][k[1] - low[1]],
                      cellOfKey[2][k[2] - low[2]]);
    if ((cell.array() < from.array()).any() || (cell.array() > to.array()).any()) return;
    combine(cell, f.occupied(value) ? CellState::Occupied : CellState::Free);
  });
}

void fillGrid(const CellBlocks& cells, VoxelGrid& grid) {
  const GridFrame whole = grid.frame();
  fillGrid(cells, whole, Index3::Zero(), grid);
}

// The map cells overlapping [min, max] plus a margin of one cell, as a dense grid at the map's
// resolution aligned with its cells; region cells are those not on the grid's border.
VoxelGrid regionGrid(const CellBlocks& cells, const Vec3& min, const Vec3& max) {
  COINSPECT_ASSERT((min.array() <= max.array()).all());
  const double r = cells.frame().resolution;
  const Index3 first = (min / r).array().floor().cast<int>() - 1;
  const Index3 last = (max / r).array().floor().cast<int>() + 1;
  VoxelGrid grid(first.cast<double>() * r, r, last - first + Index3::Ones());
  fillGrid(cells, grid);
  return grid;
}

// Face neighbours in a fixed order (-x, +x, -y, +y, -z, +z).
const std::array<Index3, 6> kFaces = {Index3(-1, 0, 0), Index3(1, 0, 0),  Index3(0, -1, 0),
                                      Index3(0, 1, 0),  Index3(0, 0, -1), Index3(0, 0, 1)};

}  // namespace

double OccupancyMap::clearance(const Vec3& point, double maxDistance) const {
  COINSPECT_ASSERT(maxDistance >= 0.0 && point.allFinite());
  const CellFrame& f = cells_->frame();
  double best2 = maxDistance * maxDistance;
  // The distance from `point` to the box [lo, hi] of cell centres: a lower bound for them all.
  const auto gap2 = [&](const Vec3& lo, const Vec3& hi) {
    const Vec3 gap = (lo - point).cwiseMax(point - hi).cwiseMax(0.0);
    return gap.squaredNorm();
  };
  const auto searchBlock = [&](const CellBlocks::Block& block) {
    if (block.occupied == 0) return;
    const Vec3 lo = queryCentre(f, block.low);
    if (gap2(lo, lo + Vec3::Constant((CellBlocks::kBlockSide - 1) * f.resolution)) >= best2) return;
    for (unsigned i = 0; i < CellBlocks::kBlockCells; ++i) {
      const float value = block.logOdds[i];
      if (value == CellBlocks::kUnknown || !f.occupied(value)) continue;
      const CellKey key = CellBlocks::keyInBlock(block, i);
      const Vec3 centre = queryCentre(f, key);
      best2 = std::min(best2, gap2(centre, centre));
    }
  };
  Key3 low, high;
  keyRange(f, point - Vec3::Constant(maxDistance), point + Vec3::Constant(maxDistance), 1, low,
           high);
  forEachBlockIn(*cells_, low, high, searchBlock);
  return std::min(std::sqrt(best2), maxDistance);
}

VoxelGrid OccupancyMap::toVoxelGrid(const Vec3& min, const Vec3& max, double resolution) const {
  COINSPECT_ASSERT(resolution > 0.0 && (min.array() < max.array()).all());
  const Index3 size = ((max - min) / resolution)
                          .array()
                          .unaryExpr([](double v) { return std::ceil(v - 1e-9); })
                          .cast<int>()
                          .cwiseMax(1);
  VoxelGrid grid(min, resolution, size);
  fillGrid(*cells_, grid);
  return grid;
}

VoxelGrid OccupancyMap::toVoxelGrid(const GridFrame& whole, const Index3& from,
                                    const Index3& to) const {
  COINSPECT_ASSERT(whole.contains(from) && whole.contains(to) &&
                   (from.array() <= to.array()).all());
  VoxelGrid part(whole.origin + from.cast<double>() * whole.resolution, whole.resolution,
                 to - from + Index3::Ones());
  fillGrid(*cells_, whole, from, part);
  return part;
}

std::vector<FrontierCluster> splitFrontierClusters(const std::vector<FrontierCluster>& clusters,
                                                   double chunk) {
  std::vector<FrontierCluster> out;
  for (const auto& cluster : clusters) {
    std::map<std::array<int64_t, 3>, FrontierCluster> parts;  // ordered: deterministic
    for (const Vec3& c : cluster.cells) {
      const std::array<int64_t, 3> key{static_cast<int64_t>(std::floor(c.x() / chunk)),
                                       static_cast<int64_t>(std::floor(c.y() / chunk)),
                                       static_cast<int64_t>(std::floor(c.z() / chunk))};
      parts[key].cells.push_back(c);
    }
    for (auto& [key, part] : parts) {
      Vec3 sum = Vec3::Zero();
      for (const Vec3& c : part.cells)
        sum += c;
      part.centroid = sum / static_cast<double>(part.cells.size());
      out.push_back(std::move(part));
    }
  }
  return out;
}

std::vector<FrontierCluster> OccupancyMap::frontierClusters(const Vec3& min, const Vec3& max,
                                                            size_t minClusterSize) const {
  const VoxelGrid grid = regionGrid(*cells_, min, max);
  const Index3 size = grid.size();
  std::vector<uint8_t> mark(grid.cellCount(), 0);  // 1 = frontier, 2 = already clustered
  for (int z = 1; z < size.z() - 1; ++z)
    for (int y = 1; y < size.y() - 1; ++y)
      for (int x = 1; x < size.x() - 1; ++x) {
        const Index3 cell(x, y, z);
        if (grid.state(cell) != CellState::Free) continue;
        for (const auto& face : kFaces)
          if (grid.state(cell + face) == CellState::Unknown) {
            mark[grid.linear(cell)] = 1;
            break;
          }
      }
  // 26-connected components in ascending (z, y, x) order of their first cell.
  std::vector<FrontierCluster> clusters;
  std::vector<Index3> stack, members;
  const auto interior = [&](const Index3& c) {
    return (c.array() >= 1).all() && (c.array() < size.array() - 1).all();
  };
  for (int z = 1; z < size.z() - 1; ++z)
    for (int y = 1; y < size.y() - 1; ++y)
      for (int x = 1; x < size.x() - 1; ++x) {
        const Index3 seed(x, y, z);
        if (mark[grid.linear(seed)] != 1) continue;
        members.clear();
        stack.assign(1, seed);
        mark[grid.linear(seed)] = 2;
        while (!stack.empty()) {
          const Index3 cell = stack.back();
          stack.pop_back();
          members.push_back(cell);
          for (int dz = -1; dz <= 1; ++dz)
            for (int dy = -1; dy <= 1; ++dy)
              for (int dx = -1; dx <= 1; ++dx) {
                const Index3 next = cell + Index3(dx, dy, dz);
                if (!interior(next) || mark[grid.linear(next)] != 1) continue;
                mark[grid.linear(next)] = 2;
                stack.push_back(next);
              }
        }
        if (members.size() < minClusterSize) continue;
        std::sort(members.begin(), members.end(), [&](const Index3& a, const Index3& b) {
          return grid.linear(a) < grid.linear(b);
        });
        FrontierCluster cluster;
        cluster.cells.reserve(members.size());
        for (const auto& cell : members) {
          cluster.cells.push_back(grid.centre(cell));
          cluster.centroid += cluster.cells.back();
        }
        cluster.centroid /= static_cast<double>(members.size());
        clusters.push_back(std::move(cluster));
      }
  return clusters;
}

std::vector<SurfaceVoxel> OccupancyMap::surfaceVoxels(const Vec3& min, const Vec3& max) const {
  const VoxelGrid grid = regionGrid(*cells_, min, max);
  const Index3 size = grid.size();
  std::vector<SurfaceVoxel> surface;
  for (int z = 1; z < size.z() - 1; ++z)
    for (int y = 1; y < size.y() - 1; ++y)
      for (int x = 1; x < size.x() - 1; ++x) {
        const Index3 cell(x, y, z);
        if (grid.state(cell) != CellState::Occupied) continue;
        // Normal: the sum of the directions toward free face neighbours. Exact on flat faces
        // (the axis), the bisector on edges and corners; a cell free on two opposite sides (a
        // wall one cell thick seen from both) keeps the first free direction in face order.
        Vec3 sum = Vec3::Zero();
        const Index3* firstFree = nullptr;
        for (const auto& face : kFaces)
          if (grid.state(cell + face) == CellState::Free) {
            sum += face.cast<double>();
            if (firstFree == nullptr) firstFree = &face;
          }
        if (firstFree == nullptr) continue;
        SurfaceVoxel voxel;
        voxel.centre = grid.centre(cell);
        voxel.normal = sum.squaredNorm() > 0.0 ? sum.normalized() : firstFree->cast<double>();
        surface.push_back(voxel);
      }
  return surface;
}

}  // namespace coinspect::mapping
