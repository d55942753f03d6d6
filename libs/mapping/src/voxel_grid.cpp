#include "coinspect/mapping/voxel_grid.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "coinspect/core/error.h"

namespace coinspect::mapping {

namespace {

// One pass of Felzenszwalb & Huttenlocher's exact 1-D squared distance transform (lower
// envelope of parabolas), applied along each axis in turn: O(n) per line.
void distanceTransform1d(const float* in, float* out, int n, std::vector<int>& v,
                         std::vector<float>& z) {
  constexpr float kInf = std::numeric_limits<float>::infinity();
  v.assign(n, 0);
  z.assign(n + 1, 0.0f);
  int k = -1;
  for (int q = 0; q < n; ++q) {
    if (in[q] == kInf) continue;
    while (k >= 0) {
      const float s = ((in[q] + q * q) - (in[v[k]] + v[k] * v[k])) / (2.0f * (q - v[k]));
      if (s > z[k]) {
        ++k;
        v[k] = q;
        z[k] = s;
        z[k + 1] = kInf;
        break;
      }
      --k;
    }
    if (k < 0) {
      k = 0;
      v[0] = q;
      z[0] = -kInf;
      z[1] = kInf;
    }
  }
  if (k < 0) {
    std::fill(out, out + n, kInf);
    return;
  }
  int j = 0;
  for (int q = 0; q < n; ++q) {
    while (z[j + 1] < q)
      ++j;
    const float d = static_cast<float>(q - v[j]);
    out[q] = d * d + in[v[j]];
  }
}

}  // namespace

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
  // Separable transform: x lines, then y, then z (squared cell distances). A pass's lines are
  // those the next passes read for the window's cells: every x line of the grown box, the y
  // lines over the window's x only, the z lines over its x and y only (each line's result is
  // the same whichever other lines are transformed).
  // A squared distance over the cap's (capCells()^2) reads as the cap in the end whatever it
  // is, and one that large after a pass stays over it after the next: such values are made
  // infinite between passes, lines with nothing finite or with only blocking cells are left as
  // they are (their transform is themselves), and in open space most lines are one or the
  // other. The values under the cap are the same exact squared distances.
  const int cap = capCells();
  // The x pass reads the states: its input is 0 (blocking) or infinite, so a cell's result is
  // the squared distance to the nearest blocking cell of its line, found by one scan each way
  // (the lower envelope of the general pass gives the same values, at several times the cost).
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
  // The y and z passes take their lines kBlock at a time, neighbours in x: a line's cells lie a
  // row or a layer apart, and gathering one line at a time missed the cache at every cell (a
  // fifth of the transform's time); neighbouring lines share each cache line fetched.
  constexpr int kBlock = 16;
  const int longest = std::max({sy, sz});
  thread_local std::vector<float> block;
  block.resize(static_cast<size_t>(kBlock) * longest);
  std::vector<float> result(longest);
  std::vector<int> v;
  std::vector<float> cuts;
  const float over = static_cast<float>(cap) * static_cast<float>(cap);
  // The `lines` lines (at most kBlock) starting at `first`, `first` + 1, ..., each `count` cells
  // `stride` apart.
  const auto transformLines = [&](size_t first, int lines, int count, size_t stride) {
    for (int q = 0; q < count; ++q) {
      const float* cells = &squared[first + q * stride];
      for (int k = 0; k < lines; ++k)
        block[static_cast<size_t>(k) * count + q] = cells[k];
    }
    bool changed[kBlock] = {};
    for (int k = 0; k < lines; ++k) {
      float* line = &block[static_cast<size_t>(k) * count];
      bool anyFinite = false, allZero = true;
      for (int q = 0; q < count; ++q) {
        anyFinite = anyFinite || line[q] != kInf;
        allZero = allZero && line[q] == 0.0f;
      }
      if (!anyFinite || allZero) continue;
      distanceTransform1d(line, result.data(), count, v, cuts);
      for (int q = 0; q < count; ++q)
        line[q] = result[q] > over ? kInf : result[q];
      changed[k] = true;
    }
    for (int q = 0; q < count; ++q) {
      float* cells = &squared[first + q * stride];
      for (int k = 0; k < lines; ++k)
        if (changed[k]) cells[k] = block[static_cast<size_t>(k) * count + q];
    }
  };
  const auto local = [&](int x, int y, int z) {
    return (static_cast<size_t>(z - from.z()) * sy + (y - from.y())) * sx + (x - from.x());
  };
  for (int z = from.z(); z <= to.z(); ++z)
    for (int x = low.x(); x <= high.x(); x += kBlock)
      transformLines(local(x, from.y(), z), std::min(kBlock, high.x() - x + 1), sy,
                     static_cast<size_t>(sx));
  for (int y = low.y(); y <= high.y(); ++y)
    for (int x = low.x(); x <= high.x(); x += kBlock)
      transformLines(local(x, y, from.z()), std::min(kBlock, high.x() - x + 1), sz,
                     static_cast<size_t>(sx) * sy);
  const float capF = static_cast<float>(clearanceCap_);
  const float res = static_cast<float>(frame_.resolution);
  for (int z = low.z(); z <= high.z(); ++z)
    for (int y = low.y(); y <= high.y(); ++y) {
      const size_t row = linear(Index3(low.x(), y, z));
      const size_t first = local(low.x(), y, z);
      for (int x = 0; x <= high.x() - low.x(); ++x)
        clearance_[row + x] = std::min(capF, std::sqrt(squared[first + x]) * res);
    }
}

}  // namespace coinspect::mapping
