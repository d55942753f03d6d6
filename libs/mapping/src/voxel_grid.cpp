#include "coinspect/mapping/voxel_grid.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "coinspect/core/error.h"

namespace coinspect::mapping {

VoxelGrid::VoxelGrid(const Vec3& origin, double resolution, const Index3& size, CellState fill)
    : frame_{origin, resolution, size} {
  COINSPECT_ASSERT(resolution > 0.0 && (size.array() >= 1).all());
  states_.assign(static_cast<size_t>(size.x()) * size.y() * size.z(), fill);
}

Index3 GridFrame::cellOf(const Vec3& point) const {
  const Vec3 scaled = (point - origin) / resolution;
  return Index3(static_cast<int>(std::floor(scaled.x())), static_cast<int>(std::floor(scaled.y())),
                static_cast<int>(std::floor(scaled.z())));
}

void VoxelGrid::computeClearance(double cap, bool unknownBlocks) {
  clearance_.assign(states_.size(), 0.0f);
  clearanceCap_ = cap;
  clearanceUnknownBlocks_ = unknownBlocks;
  transformWindow(Index3::Zero(), frame_.size - Index3::Ones());
}

void VoxelGrid::updateClearance(const Index3& low, const Index3& high) {
  COINSPECT_ASSERT(hasClearance());
  if ((low.array() > high.array()).any()) return;  // nothing changed
  // A cell's capped clearance depends only on the cells within the cap of it: the values that
  // can change are those within the cap of the changed cells.
  const Index3 reach = Index3::Constant(capCells());
  transformWindow((low - reach).cwiseMax(0), (high + reach).cwiseMin(frame_.size - Index3::Ones()));
}

int VoxelGrid::capCells() const {
  return static_cast<int>(std::ceil(clearanceCap_ / frame_.resolution)) + 1;
}

void VoxelGrid::transformWindow(const Index3& low, const Index3& high) {
  constexpr float kInf = std::numeric_limits<float>::infinity();
  // The transform reads the window grown by the cap (clipped to the grid): a blocking cell
  // farther out cannot bring a cell of the window under the cap. Over the whole grid this is the
  // whole grid, and a window's values equal the whole grid's: exact squared cell distances.
  const Index3 reach = Index3::Constant(capCells());
  const Index3 from = (low - reach).cwiseMax(0);
  const Index3 to = (high + reach).cwiseMin(frame_.size - Index3::Ones());
  const int sx = to.x() - from.x() + 1, sy = to.y() - from.y() + 1, sz = to.z() - from.z() + 1;
  // Reused: a fresh buffer of up to the whole grid per rebuild was paid in page faults.
  thread_local std::vector<float> squared;
  squared.resize(static_cast<size_t>(sx) * sy * sz);
  // Separable transform: x lines, then y, then z (squared cell distances). A pass computes
  // what the next passes read for the window's cells: every x line of the grown box, the y pass
  // over the window's x only, the z pass over its x and y only. A squared distance over the
  // cap's (capCells()^2) reads as the cap in the end whatever it is.
  const int cap = capCells();
  // The x pass reads the states: a cell's result is the squared distance to the nearest
  // blocking cell of its line, found by one scan each way (infinite beyond the cap).
  thread_local std::vector<int> before;
  before.resize(static_cast<size_t>(sx));
  constexpr int kFar = 1 << 20;  // no blocking cell on that side
  size_t i = 0;
  for (int z = from.z(); z <= to.z(); ++z)
    for (int y = from.y(); y <= to.y(); ++y, i += static_cast<size_t>(sx)) {
      const CellState* row = &states_[linear(Index3(from.x(), y, z))];
      int last = -kFar;
      for (int x = 0; x < sx; ++x) {
        if (blocksClearance(row[x])) last = x;
        before[x] = x - last;
      }
      int next = kFar;
      for (int x = sx - 1; x >= 0; --x) {
        if (before[x] == 0) next = x;
        const int d = std::min(before[x], next - x);
        squared[i + x] = d > cap ? kInf : static_cast<float>(d * d);
      }
    }
  // The y and z passes: a window cell's squared distance is the least over the cells k <= cap
  // away along the axis of their value plus k^2. A squared distance under the cap's comes from a
  // blocking cell within the cap along every axis, so those values are exact; the others end over
  // the cap's and read as the cap (as infinite ones do). Both passes take whole rows of the
  // window's x cells, neighbours in memory, the rows k before and after at once (vectorised by
  // the compiler): gathering strided lines for the lower envelope of parabolas, as this did
  // until 2026-12-07, took about twice as long (doc/benchmarks.md, "Path search").
  const int wx = high.x() - low.x() + 1, wy = high.y() - low.y() + 1;
  // out = the least of row(at) + (at - centre)^2 over at within cap of centre and [first, last].
  const auto lowest = [&](float* __restrict out, int centre, int first, int last, const auto& row) {
    std::copy_n(row(centre), wx, out);
    for (int k = 1; k <= cap; ++k) {
      const float k2 = static_cast<float>(k * k);
      const float* __restrict a = centre - k >= first ? row(centre - k) : nullptr;
      const float* __restrict b = centre + k <= last ? row(centre + k) : nullptr;
      if (a && b) {
        for (int x = 0; x < wx; ++x)
          out[x] = std::min(out[x], std::min(a[x], b[x]) + k2);
      } else if (a || b) {
        const float* __restrict in = a ? a : b;
        for (int x = 0; x < wx; ++x)
          out[x] = std::min(out[x], in[x] + k2);
      }
    }
  };
  // y pass: the window's x and y, every z of the grown box, into `alongY` (wx * wy per layer).
  thread_local std::vector<float> alongY;
  alongY.resize(static_cast<size_t>(wx) * wy * sz);
  const auto inY = [&](int y, int z) {
    return &alongY[(static_cast<size_t>(z - from.z()) * wy + (y - low.y())) * wx];
  };
  for (int z = from.z(); z <= to.z(); ++z)
    for (int y = low.y(); y <= high.y(); ++y)
      lowest(inY(y, z), y, from.y(), to.y(), [&](int at) {
        return &squared[(static_cast<size_t>(z - from.z()) * sy + (at - from.y())) * sx +
                        (low.x() - from.x())];
      });
  // z pass: the window's cells, then their clearance from a table by squared distance (one
  // entry past the cap's for every larger one): the same values as the square root's.
  const float capF = static_cast<float>(clearanceCap_);
  const float res = static_cast<float>(frame_.resolution);
  const int over = cap * cap + 1;
  thread_local std::vector<float> metres;
  metres.resize(static_cast<size_t>(over) + 1);
  for (int d = 0; d <= over; ++d)
    metres[d] = std::min(capF, std::sqrt(static_cast<float>(d)) * res);
  thread_local std::vector<float> alongZ;
  alongZ.resize(static_cast<size_t>(wx));
  for (int z = low.z(); z <= high.z(); ++z)
    for (int y = low.y(); y <= high.y(); ++y) {
      lowest(alongZ.data(), z, from.z(), to.z(), [&](int at) { return inY(y, at); });
      float* row = &clearance_[linear(Index3(low.x(), y, z))];
      for (int x = 0; x < wx; ++x)
        row[x] = metres[static_cast<size_t>(std::min(alongZ[x], static_cast<float>(over)))];
    }
}

}  // namespace coinspect::mapping
