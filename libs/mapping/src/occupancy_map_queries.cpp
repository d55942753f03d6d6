// OccupancyMap queries: clearance, dense snapshots, frontier clusters, surface voxels.
//
// All of them walk the octree depth first from the root and skip whole subtrees by their key
// box (outside the region asked for) or by their inner value: the batched update keeps every
// inner node at the maximum log-odds of its children (batch_octree.h), so a subtree whose root is
// not occupied holds no occupied cell.
#include <algorithm>
#include <array>
#include <cmath>
#include <map>

#include "batch_octree.h"
#include "coinspect/core/error.h"
#include "coinspect/mapping/occupancy_map.h"

namespace coinspect::mapping {

namespace {

using Key3 = Eigen::Array3i;  // key coordinates of a node's minimum corner (0..65535)

// The keys of a node's child `index` (OctoMap's computeChildIdx: x bit 0, y bit 1, z bit 2).
inline Key3 childCorner(const Key3& corner, unsigned index, int childSize) {
  return corner + Key3(index & 1U, (index >> 1) & 1U, (index >> 2) & 1U) * childSize;
}

struct TreeFrame {
  const octomap::OcTree& tree;
  double resolution;
  int depth;    // tree depth (16)
  int keyZero;  // key of the cell whose minimum corner is the world origin (32768)

  explicit TreeFrame(const octomap::OcTree& t)
      : tree(t),
        resolution(t.getResolution()),
        depth(static_cast<int>(t.getTreeDepth())),
        keyZero(static_cast<int>(t.coordToKey(0.0))) {}

  Vec3 corner(const Key3& key) const {
    return (key - keyZero).cast<double>().matrix() * resolution;
  }
};

// Nearest occupied cell centre to q, by branch and bound over the tree.
void nearestOccupied(const TreeFrame& f, const octomap::OcTreeNode* node, int depth,
                     const Key3& corner, const Vec3& q, double& best2) {
  if (!f.tree.isNodeOccupied(node)) return;  // no occupied cell below
  const int size = 1 << (f.depth - depth);
  // The cell centres below lie in [lo, hi]: a lower bound of their distance to q.
  const Vec3 lo = f.corner(corner) + Vec3::Constant(0.5 * f.resolution);
  const Vec3 hi = lo + Vec3::Constant((size - 1) * f.resolution);
  const Vec3 gap = (lo - q).cwiseMax(q - hi).cwiseMax(0.0);
  const double d2 = gap.squaredNorm();
  if (d2 >= best2) return;
  if (depth == f.depth) {
    best2 = d2;
    return;
  }
  for (unsigned i = 0; i < 8; ++i)
    if (f.tree.nodeChildExists(node, i))
      nearestOccupied(f, f.tree.getNodeChild(node, i), depth + 1, childCorner(corner, i, size / 2),
                      q, best2);
}

// Fills `part`, the cells [from, from + part size) of a grid of frame `whole`, from the tree: a
// dense cell is Occupied if a map cell inside it is, else Free if one is known. Cells are found
// in the whole grid's frame, so that a cell reads the same in a part as in the whole grid.
// `stopDepth` < tree depth when the grid's cells are exactly the nodes of that depth (aligned,
// resolution x 2^k): then a node's inner value already answers for its cell.
class GridFiller {
 public:
  GridFiller(const TreeFrame& frame, const GridFrame& whole, const Index3& from, VoxelGrid& part,
             int stopDepth)
      : f_(frame),
        whole_(whole),
        from_(from),
        to_(from + part.size() - Index3::Ones()),
        part_(part),
        stopDepth_(stopDepth) {
    partMin_ = whole.origin + from_.cast<double>() * whole.resolution;
    partMax_ = whole.origin + (to_ + Index3::Ones()).cast<double>() * whole.resolution;
    tabulateStopNodes();
  }

  void visit(const octomap::OcTreeNode* node, int depth, const Key3& corner) {
    if (depth == stopDepth_ && tabulated_ && (corner >= keyLow_).all() &&
        (corner <= keyHigh_).all()) {
      // What the general path below computes for this node, looked up per axis.
      const Key3 k = corner - keyLow_;
      if (!overlaps_[0][k[0]] || !overlaps_[1][k[1]] || !overlaps_[2][k[2]]) return;
      const CellState state = f_.tree.isNodeOccupied(node) ? CellState::Occupied : CellState::Free;
      const Index3 cell(cells_[0][k[0]], cells_[1][k[1]], cells_[2][k[2]]);
      if (inPart(cell)) combine(cell, state);
      return;
    }
    const int size = 1 << (f_.depth - depth);
    const Vec3 lo = f_.corner(corner);
    const Vec3 hi = lo + Vec3::Constant(size * f_.resolution);
    if ((hi.array() <= partMin_.array()).any() || (lo.array() >= partMax_.array()).any()) return;
    if (depth == stopDepth_ || !f_.tree.nodeHasChildren(node)) {
      const CellState state = f_.tree.isNodeOccupied(node) ? CellState::Occupied : CellState::Free;
      if (size * f_.resolution <= whole_.resolution * (1.0 + 1e-9)) {
        const Index3 cell = whole_.cellOf(lo + Vec3::Constant(0.5 * size * f_.resolution));
        if (inPart(cell)) combine(cell, state);
        return;
      }
      // A node larger than a dense cell: every dense cell whose centre it holds.
      const Index3 first = whole_.cellOf(lo).cwiseMax(from_);
      const Index3 last = whole_.cellOf(hi).cwiseMin(to_);
      for (int z = first.z(); z <= last.z(); ++z)
        for (int y = first.y(); y <= last.y(); ++y)
          for (int x = first.x(); x <= last.x(); ++x) {
            const Index3 cell(x, y, z);
            const Vec3 c = whole_.centre(cell);
            if ((c.array() >= lo.array()).all() && (c.array() < hi.array()).all())
              combine(cell, state);
          }
      return;
    }
    for (unsigned i = 0; i < 8; ++i)
      if (f_.tree.nodeChildExists(node, i))
        visit(f_.tree.getNodeChild(node, i), depth + 1, childCorner(corner, i, size / 2));
  }

 private:
  // Most visits end at a node of stopDepth_ no larger than a dense cell (a map cell, when the
  // resolutions are equal): its overlap with the part and its dense cell depend on each key
  // component alone (corner, cellOf and the box test work per component), so they are computed
  // once per key value of the part's range, by the same expressions, instead of per node (with
  // the sanitizers, where these helpers are calls, the copy was a quarter of a mission's time).
  void tabulateStopNodes() {
    const int size = 1 << (f_.depth - stopDepth_);
    if (size * f_.resolution > whole_.resolution * (1.0 + 1e-9)) return;
    const Vec3 half = Vec3::Constant(0.5 * size * f_.resolution);
    for (int a = 0; a < 3; ++a) {
      // Keys (node corners, multiples of size) of the nodes that may overlap the part, with a
      // node of margin each side.
      const int low = static_cast<int>(std::floor(partMin_[a] / f_.resolution)) + f_.keyZero;
      const int high = static_cast<int>(std::ceil(partMax_[a] / f_.resolution)) + f_.keyZero;
      keyLow_[a] = std::max(0, (low / size - 1) * size);
      keyHigh_[a] = std::min((1 << f_.depth) - size, (high / size + 1) * size);
      overlaps_[a].assign(static_cast<size_t>(keyHigh_[a] - keyLow_[a] + 1), 0);
      cells_[a].assign(overlaps_[a].size(), 0);
      for (int key = keyLow_[a]; key <= keyHigh_[a]; ++key) {
        const Vec3 lo = f_.corner(Key3::Constant(key));
        const Vec3 hi = lo + Vec3::Constant(size * f_.resolution);
        overlaps_[a][key - keyLow_[a]] = !(hi[a] <= partMin_[a] || lo[a] >= partMax_[a]);
        cells_[a][key - keyLow_[a]] = whole_.cellOf(lo + half)[a];
      }
    }
    tabulated_ = true;
  }

  bool inPart(const Index3& cell) const {
    return (cell.array() >= from_.array()).all() && (cell.array() <= to_.array()).all();
  }
  void combine(const Index3& wholeCell, CellState state) {  // wholeCell is in the part
    const size_t index = part_.linear(wholeCell - from_);
    if (state == CellState::Occupied || part_.stateAt(index) == CellState::Unknown)
      part_.setAt(index, state);
  }

  const TreeFrame& f_;
  const GridFrame& whole_;
  Index3 from_, to_;
  VoxelGrid& part_;
  int stopDepth_;
  Vec3 partMin_, partMax_;
  bool tabulated_ = false;  // tabulateStopNodes() applies
  Key3 keyLow_ = Key3::Zero(), keyHigh_ = Key3::Constant(-1);
  std::array<std::vector<uint8_t>, 3> overlaps_;  // per axis, per key from keyLow_
  std::array<std::vector<int>, 3> cells_;
};

// `part` holds the cells from `from` on of a grid of frame `whole` (part.size() of them).
void fillGrid(const octomap::OcTree& tree, const GridFrame& whole, const Index3& from,
              VoxelGrid& part) {
  const TreeFrame frame(tree);
  // Aligned grids of resolution x 2^k stop k levels above the leaves.
  int stopDepth = frame.depth;
  const double ratio = whole.resolution / frame.resolution;
  const int k = static_cast<int>(std::lround(std::log2(ratio)));
  if (k > 0 && k < frame.depth && std::abs(ratio - std::ldexp(1.0, k)) < 1e-9 * ratio) {
    const Vec3 steps = whole.origin / whole.resolution;
    if (((steps.array() - steps.array().round()).abs() < 1e-6).all()) stopDepth = frame.depth - k;
  }
  if (tree.getRoot() == nullptr) return;
  GridFiller(frame, whole, from, part, stopDepth).visit(tree.getRoot(), 0, Key3::Zero());
}

void fillGrid(const octomap::OcTree& tree, VoxelGrid& grid) {
  const GridFrame whole = grid.frame();
  fillGrid(tree, whole, Index3::Zero(), grid);
}

// The map cells overlapping [min, max] plus a margin of one cell, as a dense grid at the map's
// resolution aligned with its cells; region cells are those not on the grid's border.
VoxelGrid regionGrid(const octomap::OcTree& tree, const Vec3& min, const Vec3& max) {
  COINSPECT_ASSERT((min.array() <= max.array()).all());
  const double r = tree.getResolution();
  const Index3 first = (min / r).array().floor().cast<int>() - 1;
  const Index3 last = (max / r).array().floor().cast<int>() + 1;
  VoxelGrid grid(first.cast<double>() * r, r, last - first + Index3::Ones());
  fillGrid(tree, grid);
  return grid;
}

// Face neighbours in a fixed order (-x, +x, -y, +y, -z, +z).
const std::array<Index3, 6> kFaces = {Index3(-1, 0, 0), Index3(1, 0, 0),  Index3(0, -1, 0),
                                      Index3(0, 1, 0),  Index3(0, 0, -1), Index3(0, 0, 1)};

}  // namespace

double OccupancyMap::clearance(const Vec3& point, double maxDistance) const {
  COINSPECT_ASSERT(maxDistance >= 0.0);
  const octomap::OcTreeNode* root = tree_->getRoot();
  if (root == nullptr) return maxDistance;
  double best2 = maxDistance * maxDistance;
  nearestOccupied(TreeFrame(*tree_), root, 0, Key3::Zero(), point, best2);
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
  fillGrid(*tree_, grid);
  return grid;
}

VoxelGrid OccupancyMap::toVoxelGrid(const GridFrame& whole, const Index3& from,
                                    const Index3& to) const {
  COINSPECT_ASSERT(whole.contains(from) && whole.contains(to) &&
                   (from.array() <= to.array()).all());
  VoxelGrid part(whole.origin + from.cast<double>() * whole.resolution, whole.resolution,
                 to - from + Index3::Ones());
  fillGrid(*tree_, whole, from, part);
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
  const VoxelGrid grid = regionGrid(*tree_, min, max);
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
  const VoxelGrid grid = regionGrid(*tree_, min, max);
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
