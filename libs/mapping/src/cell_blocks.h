// Internal: the cells of an OccupancyMap, in blocks of 8 x 8 x 8 cells allocated where something
// was observed. OctoMap's cell keys, log-odds arithmetic and sensor model are kept, so a map is
// cell for cell what an octomap::OcTree fed the same updates holds (unit tests compare them), but
// a cell costs 4 bytes in its block instead of a tree node (a 16-byte node in a 32-byte heap
// chunk, plus its share of the parent's child array and of the inner nodes above): 9 bytes per
// known cell against 53 for a never pruned tree, measured on a map of the MBS structure
// (bench_mapping, BM_MapHeap). Updates and reads are array accesses within a block instead of
// 16-level pointer walks.
//
// Codes: an update code is (Morton code of the cell key) << 1 | occupied. The Morton code
// interleaves the 16-bit key components with x in the lowest bit of each triple; its low 9 bits
// are the cell within its block, the bits above them the block's own Morton code, so sorting
// codes groups the cells of one block.
#pragma once

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <unordered_map>
#include <vector>

#include "coinspect/mapping/voxel_grid.h"  // Vec3

namespace coinspect::mapping {

using CellKey = std::array<uint16_t, 3>;

constexpr uint64_t spreadBits16(uint64_t v) {
  v &= 0xffffULL;
  v = (v | (v << 16)) & 0x0000ff0000ffULL;
  v = (v | (v << 8)) & 0x00f00f00f00fULL;
  v = (v | (v << 4)) & 0x0c30c30c30c3ULL;
  v = (v | (v << 2)) & 0x249249249249ULL;
  return v;
}

constexpr uint64_t compactBits16(uint64_t v) {
  v &= 0x249249249249ULL;
  v = (v | (v >> 2)) & 0x0c30c30c30c3ULL;
  v = (v | (v >> 4)) & 0x00f00f00f00fULL;
  v = (v | (v >> 8)) & 0x0000ff0000ffULL;
  v = (v | (v >> 16)) & 0xffffULL;
  return v;
}

inline uint64_t mortonOf(const CellKey& key) {
  return spreadBits16(key[0]) | (spreadBits16(key[1]) << 1) | (spreadBits16(key[2]) << 2);
}

constexpr CellKey keyOfMorton(uint64_t morton) {
  return {static_cast<uint16_t>(compactBits16(morton)),
          static_cast<uint16_t>(compactBits16(morton >> 1)),
          static_cast<uint16_t>(compactBits16(morton >> 2))};
}

// The Morton code of the cell one step (`step` +1 or -1) along `axis` (0 x, 1 y, 2 z): the
// component's bits are counted up or down in place (the carry or borrow passes through the other
// components' bits), wrapping at 2^16 like a key component.
inline uint64_t stepMorton(uint64_t morton, int axis, int step) {
  const uint64_t bits = 0x249249249249ULL << axis;
  const uint64_t moved = step > 0 ? ((morton | ~bits) + 1) & bits : ((morton & bits) - 1) & bits;
  return (morton & ~bits) | moved;
}

inline uint64_t updateCode(const CellKey& key, bool occupied) {
  return (mortonOf(key) << 1) | (occupied ? 1U : 0U);
}

// Sorts `codes` ascending (LSD radix sort, 11-bit digits, passes whose digit is constant
// skipped), removes repeated cells keeping the occupied code of a cell when there is one.
void sortUniqueCodes(std::vector<uint64_t>& codes, std::vector<uint64_t>& buffer);

// OctoMap's key arithmetic (OcTreeBaseImpl: 16 levels, keys centred on 32768) and its default
// sensor model, read from an octomap::OcTree once.
struct CellFrame {
  static constexpr int kKeyZero = 32768;  // the key of the cell whose minimum corner is 0
  double resolution = 0.5;
  double factor = 2.0;  // 1 / resolution, as OctoMap computes it
  float hitLog = 0.0f, missLog = 0.0f, clampMinLog = 0.0f, clampMaxLog = 0.0f, occupiedLog = 0.0f;

  explicit CellFrame(double resolution);

  // false beyond the +-2^15 cells around the origin (and for non-finite coordinates).
  bool keyOf(double coordinate, uint16_t& key) const {
    const double scaled = std::floor(factor * coordinate);
    if (!(scaled >= -kKeyZero && scaled < kKeyZero)) return false;
    key = static_cast<uint16_t>(static_cast<int>(scaled) + kKeyZero);
    return true;
  }
  bool keyOf(const Vec3& p, CellKey& key) const {
    return keyOf(p.x(), key[0]) && keyOf(p.y(), key[1]) && keyOf(p.z(), key[2]);
  }
  double centreOf(uint16_t key) const {
    return (static_cast<double>(static_cast<int>(key) - kKeyZero) + 0.5) * resolution;
  }
  Vec3 centreOf(const CellKey& key) const {
    return Vec3(centreOf(key[0]), centreOf(key[1]), centreOf(key[2]));
  }
  // The centre rounded to float, as OctoMap's keyToCoord(OcTreeKey) gives it (its ray ends and
  // the points its rules are asked about).
  Eigen::Vector3f floatCentreOf(const CellKey& key) const {
    return Eigen::Vector3f(static_cast<float>(centreOf(key[0])),
                           static_cast<float>(centreOf(key[1])),
                           static_cast<float>(centreOf(key[2])));
  }
  bool occupied(float logOdds) const { return logOdds >= occupiedLog; }
};

class CellBlocks {
 public:
  static constexpr int kBlockBits = 3;  // 8 cells a side
  static constexpr int kBlockSide = 1 << kBlockBits;
  static constexpr int kBlockCells = kBlockSide * kBlockSide * kBlockSide;

  struct Block {
    CellKey low{};                           // key of its first cell
    std::array<float, kBlockCells> logOdds;  // by in-block Morton code; kUnknown: never observed
    uint16_t known = 0, occupied = 0;
  };
  static constexpr float kUnknown = -1e30f;  // below any clamped log-odds
  static constexpr std::array<std::array<uint8_t, 3>, kBlockCells> kCellOffsets = [] {
    std::array<std::array<uint8_t, 3>, kBlockCells> table{};
    for (unsigned i = 0; i < kBlockCells; ++i) {
      const CellKey key = keyOfMorton(i);
      table[i] = {static_cast<uint8_t>(key[0]), static_cast<uint8_t>(key[1]),
                  static_cast<uint8_t>(key[2])};
    }
    return table;
  }();

  explicit CellBlocks(double resolution) : frame_(resolution) {}

  const CellFrame& frame() const { return frame_; }

  // Applies one hit or miss to each cell of `codes` (sorted ascending, one code per cell); with
  // `missesClearOccupied` false, a miss leaves an occupied cell as it is, unless `clearAt` (when
  // given) says so for the cell's centre.
  void applySorted(const std::vector<uint64_t>& codes, bool missesClearOccupied,
                   const std::function<bool(const Vec3&)>* clearAt = nullptr);

  // Appends one update code per known cell (occupied or free as the cell is), unsorted.
  void appendCodes(std::vector<uint64_t>& codes) const;

  // The block holding the cell of Morton code `morton`, nullptr when none was allocated.
  const Block* blockOf(uint64_t morton) const;
  // Every allocated block, in the order they were first observed.
  const std::vector<std::unique_ptr<Block>>& blocks() const { return blocks_; }
  // The log-odds of a cell (kUnknown when never observed).
  float logOdds(const CellKey& key) const;
  // The offset of cell `index` (in-block Morton code) from its block's first cell.
  static const std::array<uint8_t, 3>& cellOffset(unsigned index) { return kCellOffsets[index]; }
  static CellKey keyInBlock(const Block& block, unsigned index) {
    const auto& offset = cellOffset(index);
    return {static_cast<uint16_t>(block.low[0] + offset[0]),
            static_cast<uint16_t>(block.low[1] + offset[1]),
            static_cast<uint16_t>(block.low[2] + offset[2])};
  }

  size_t knownCells() const { return known_; }
  size_t occupiedCells() const { return occupied_; }

  // The key box of the cells whose state (unknown, free, occupied) changed since the last
  // takeChangedKeys(), which empties it; empty: low > high.
  struct KeyBox {
    std::array<int, 3> low{65536, 65536, 65536}, high{-1, -1, -1};
    bool empty() const { return low[0] > high[0]; }
  };
  KeyBox takeChangedKeys();

 private:
  Block& blockFor(uint64_t blockMorton);  // allocates it when needed
  void noteChanged(uint64_t code);

  CellFrame frame_;
  std::unordered_map<uint64_t, uint32_t> index_;  // block Morton code -> position in blocks_
  std::vector<std::unique_ptr<Block>> blocks_;
  KeyBox changed_;
  size_t known_ = 0;
  size_t occupied_ = 0;
};

}  // namespace coinspect::mapping
