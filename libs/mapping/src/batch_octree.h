// Internal: an octomap::OcTree that applies a whole batch of cell updates in one depth-first
// descent. OctoMap's own updateNode searches the tree and then descends it again for every cell
// (two 16-level walks per cell) and, unless lazy, refreshes the inner nodes of the path each
// time; here the updates are sorted by Morton code (the tree's depth-first order), so every node
// on the way is visited once per batch and its inner occupancy (max of its children) is
// refreshed once, on the way back up. The inner nodes are therefore always current: queries may
// prune subtrees by their inner value without an updateInnerOccupancy() pass.
//
// The tree is never pruned (it would make leaves of different sizes and cost a check per
// update); OccupancyMap owns it and exposes it only as const.
#pragma once

#include <octomap/OcTree.h>

#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <vector>

#include "coinspect/mapping/voxel_grid.h"  // Vec3

namespace coinspect::mapping {

// An update code is (Morton code of the leaf key) << 1 | occupied. The Morton code interleaves
// the 16-bit key components with x in the lowest bit of each triple, so its 3-bit groups from the
// top are OctoMap's child indices from the root down (computeChildIdx).
inline uint64_t spreadBits16(uint64_t v) {
  v &= 0xffffULL;
  v = (v | (v << 16)) & 0x0000ff0000ffULL;
  v = (v | (v << 8)) & 0x00f00f00f00fULL;
  v = (v | (v << 4)) & 0x0c30c30c30c3ULL;
  v = (v | (v << 2)) & 0x249249249249ULL;
  return v;
}

inline uint64_t mortonOf(const octomap::OcTreeKey& key) {
  return spreadBits16(key[0]) | (spreadBits16(key[1]) << 1) | (spreadBits16(key[2]) << 2);
}

// The Morton code of the cell one step (`step` +1 or -1) along `axis` (0 x, 1 y, 2 z): the
// component's bits are counted up or down in place (the carry or borrow passes through the other
// components' bits), wrapping at 2^16 like an OcTreeKey component.
inline uint64_t stepMorton(uint64_t morton, int axis, int step) {
  const uint64_t bits = 0x249249249249ULL << axis;
  const uint64_t moved = step > 0 ? ((morton | ~bits) + 1) & bits : ((morton & bits) - 1) & bits;
  return (morton & ~bits) | moved;
}

inline uint64_t updateCode(const octomap::OcTreeKey& key, bool occupied) {
  return (mortonOf(key) << 1) | (occupied ? 1U : 0U);
}

inline uint64_t compactBits16(uint64_t v) {
  v &= 0x249249249249ULL;
  v = (v | (v >> 2)) & 0x0c30c30c30c3ULL;
  v = (v | (v >> 4)) & 0x00f00f00f00fULL;
  v = (v | (v >> 8)) & 0x0000ff0000ffULL;
  v = (v | (v >> 16)) & 0xffffULL;
  return v;
}

inline octomap::OcTreeKey keyOfCode(uint64_t code) {
  const uint64_t morton = code >> 1;
  return octomap::OcTreeKey(static_cast<octomap::key_type>(compactBits16(morton)),
                            static_cast<octomap::key_type>(compactBits16(morton >> 1)),
                            static_cast<octomap::key_type>(compactBits16(morton >> 2)));
}

// Sorts `codes` ascending (LSD radix sort, 11-bit digits, passes whose digit is constant
// skipped), removes repeated cells keeping the occupied code of a cell when there is one.
void sortUniqueCodes(std::vector<uint64_t>& codes, std::vector<uint64_t>& buffer);

class BatchOcTree : public octomap::OcTree {
 public:
  explicit BatchOcTree(double resolution) : octomap::OcTree(resolution) {}

  // Applies one hit or miss to each cell of `codes` (sorted ascending, one code per cell); with
  // `missesClearOccupied` false, a miss leaves an occupied cell as it is, unless `clearAt` (when
  // given) says so for the cell's centre.
  void applySorted(const std::vector<uint64_t>& codes, bool missesClearOccupied,
                   const std::function<bool(const Vec3&)>* clearAt = nullptr);

  // Appends one update code per leaf (occupied or free as the leaf is), in ascending order: the
  // depth-first walk in child-index order is the Morton order.
  void appendLeafCodes(std::vector<uint64_t>& codes) const;

  size_t knownCells() const { return known_; }
  size_t occupiedCells() const { return occupied_; }

  // The key box of the leaves whose state (unknown, free, occupied) changed since the last
  // takeChangedKeys(), which empties it; empty: low > high.
  struct KeyBox {
    std::array<int, 3> low{65536, 65536, 65536}, high{-1, -1, -1};
    bool empty() const { return low[0] > high[0]; }
  };
  KeyBox takeChangedKeys();

 private:
  void descend(octomap::OcTreeNode* node, bool justCreated, unsigned depth, const uint64_t* begin,
               const uint64_t* end, bool missesClearOccupied);
  bool missClears(uint64_t code) const;
  const std::function<bool(const Vec3&)>* clearAt_ = nullptr;  // during applySorted
  void appendLeafCodes(const octomap::OcTreeNode* node, unsigned depth, uint64_t morton,
                       std::vector<uint64_t>& codes) const;

  void noteChanged(uint64_t code);

  KeyBox changed_;
  size_t known_ = 0;     // leaves (each a cell: the tree is never pruned)
  size_t occupied_ = 0;  // leaves with log-odds >= the occupancy threshold
};

}  // namespace coinspect::mapping
