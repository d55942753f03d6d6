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
    : origin_(origin), resolution_(resolution), size_(size) {
  COINSPECT_ASSERT(resolution > 0.0 && (size.array() >= 1).all());
  states_.assign(static_cast<size_t>(size.x()) * size.y() * size.z(), fill);
}

Index3 VoxelGrid::cellOf(const Vec3& point) const {
  const Vec3 scaled = (point - origin_) / resolution_;
  return Index3(static_cast<int>(std::floor(scaled.x())), static_cast<int>(std::floor(scaled.y())),
                static_cast<int>(std::floor(scaled.z())));
}

void VoxelGrid::computeClearance(double cap, bool unknownBlocks) {
  constexpr float kInf = std::numeric_limits<float>::infinity();
  const size_t n = states_.size();
  std::vector<float> squared(n);
  for (size_t i = 0; i < n; ++i) {
    const bool blocks =
        states_[i] == CellState::Occupied || (unknownBlocks && states_[i] == CellState::Unknown);
    squared[i] = blocks ? 0.0f : kInf;
  }
  // Separable transform: x lines, then y, then z (squared cell distances).
  const int sx = size_.x(), sy = size_.y(), sz = size_.z();
  const int longest = std::max({sx, sy, sz});
  std::vector<float> line(longest), result(longest);
  std::vector<int> v;
  std::vector<float> z;
  const auto pass = [&](int count, int stride, auto firstOf, int lines) {
    for (int l = 0; l < lines; ++l) {
      const size_t first = firstOf(l);
      for (int q = 0; q < count; ++q)
        line[q] = squared[first + static_cast<size_t>(q) * stride];
      distanceTransform1d(line.data(), result.data(), count, v, z);
      for (int q = 0; q < count; ++q)
        squared[first + static_cast<size_t>(q) * stride] = result[q];
    }
  };
  pass(
      sx, 1, [&](int l) { return static_cast<size_t>(l) * sx; }, sy * sz);
  pass(
      sy, sx, [&](int l) { return static_cast<size_t>(l / sx) * sx * sy + l % sx; }, sx * sz);
  pass(
      sz, sx * sy, [&](int l) { return static_cast<size_t>(l); }, sx * sy);
  clearance_.resize(n);
  const float capF = static_cast<float>(cap);
  for (size_t i = 0; i < n; ++i)
    clearance_[i] = std::min(capF, std::sqrt(squared[i]) * static_cast<float>(resolution_));
}

}  // namespace coinspect::mapping
