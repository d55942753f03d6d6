// A dense, axis-aligned snapshot of a robot's occupancy over a bounded region, for path search.
// The OccupancyMap is the robot's memory; planners query this grid instead because A* touches
// millions of cells: a dense array lookup, with the clearance beside it, is far cheaper than a
// map lookup (a hash of the cell's block) and a distance search.
// The clearance field holds, per cell, the Euclidean distance (m) from the cell centre to the
// nearest blocked cell centre (occupied, and unknown when the caller said so), capped.
#pragma once

#include <Eigen/Core>

#include <cstdint>
#include <vector>

namespace coinspect::mapping {

using Vec3 = Eigen::Vector3d;
using Index3 = Eigen::Vector3i;

enum class CellState : uint8_t { Unknown = 0, Free = 1, Occupied = 2 };

// A grid's geometry without its cells: which cell holds a point, and the cells' order. Cheap to
// copy, for whoever must index a grid's cells without holding the grid.
struct GridFrame {
  Vec3 origin = Vec3::Zero();  // the minimum corner of cell (0, 0, 0)
  double resolution = 1.0;
  Index3 size = Index3::Zero();

  bool contains(const Index3& cell) const {
    return (cell.array() >= 0).all() && (cell.array() < size.array()).all();
  }
  Index3 cellOf(const Vec3& point) const;  // may lie outside: check contains()
  Vec3 centre(const Index3& cell) const {
    return origin + (cell.cast<double>().array() + 0.5).matrix() * resolution;
  }
  size_t linear(const Index3& cell) const {
    return (static_cast<size_t>(cell.z()) * size.y() + cell.y()) * size.x() + cell.x();
  }
};

class VoxelGrid {
 public:
  VoxelGrid() = default;
  // `origin` is the minimum corner of cell (0, 0, 0); every size component must be >= 1.
  VoxelGrid(const Vec3& origin, double resolution, const Index3& size,
            CellState fill = CellState::Unknown);

  const GridFrame& frame() const { return frame_; }
  const Vec3& origin() const { return frame_.origin; }
  double resolution() const { return frame_.resolution; }
  const Index3& size() const { return frame_.size; }
  size_t cellCount() const { return states_.size(); }

  bool contains(const Index3& cell) const { return frame_.contains(cell); }
  Index3 cellOf(const Vec3& point) const { return frame_.cellOf(point); }
  Vec3 centre(const Index3& cell) const { return frame_.centre(cell); }
  size_t linear(const Index3& cell) const { return frame_.linear(cell); }

  // Cells outside the grid read as Unknown.
  CellState state(const Index3& cell) const {
    return contains(cell) ? states_[linear(cell)] : CellState::Unknown;
  }
  void set(const Index3& cell, CellState state) { states_[linear(cell)] = state; }
  // By linear index, unchecked: for loops over cells known to be inside (where the check of
  // state() was, with the sanitizers, a call per cell).
  CellState stateAt(size_t index) const { return states_[index]; }
  void setAt(size_t index, CellState state) { states_[index] = state; }

  // Recomputes the clearance field (exact Euclidean distance transform, capped at `cap` m).
  // Occupied cells always block; unknown cells block when `unknownBlocks`; outside the grid
  // nothing blocks. Cost O(cells).
  void computeClearance(double cap, bool unknownBlocks);
  // After set() changed cells inside [low, high] (inclusive; low > high: none), brings the
  // clearance field up to date at the cost of that box grown by the cap, not of the grid. The
  // values equal those of computeClearance() with the same arguments. Requires computeClearance().
  void updateClearance(const Index3& low, const Index3& high);
  bool hasClearance() const { return !clearance_.empty(); }
  // Whether a cell in `state` blocks the clearance field (as computeClearance() was told): a
  // change between two states that both block, or both do not, leaves the field as it is.
  bool blocksClearance(CellState state) const {
    return state == CellState::Occupied || (clearanceUnknownBlocks_ && state == CellState::Unknown);
  }
  // Distance (m) to the nearest blocking cell centre; 0 on blocking cells, `cap` when none is
  // nearer. Cells outside the grid: 0. Requires computeClearance().
  float clearance(const Index3& cell) const {
    return contains(cell) ? clearance_[linear(cell)] : 0.0f;
  }

 private:
  GridFrame frame_;
  std::vector<CellState> states_;
  std::vector<float> clearance_;
  double clearanceCap_ = 0.0;  // the arguments of the last computeClearance()
  bool clearanceUnknownBlocks_ = false;

  int capCells() const;  // the cap in cells, rounded up, plus one
  // Recomputes the clearance of the cells in [low, high] (inclusive).
  void transformWindow(const Index3& low, const Index3& high);
};

}  // namespace coinspect::mapping
