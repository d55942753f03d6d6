#include "coinspect/strategies/coinspect/work_partition.h"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "coinspect/core/error.h"

namespace coinspect::strategies::coinspect_strategy {

namespace {

void bisect(const std::vector<WorkItem>& items, std::vector<uint32_t> indices,
            const std::vector<double>& capacities, uint32_t firstRegion, uint32_t regionCount,
            std::vector<uint32_t>& out) {
  if (regionCount == 1 || indices.empty()) {
    for (const uint32_t i : indices)
      out[i] = firstRegion;
    return;
  }
  // Split along the axis of largest extent (ties: x, then y, then z).
  Vec3 low = Vec3::Constant(1e300), high = Vec3::Constant(-1e300);
  for (const uint32_t i : indices) {
    low = low.cwiseMin(items[i].position);
    high = high.cwiseMax(items[i].position);
  }
  int axis = 0;
  (high - low).maxCoeff(&axis);
  std::stable_sort(indices.begin(), indices.end(), [&](uint32_t a, uint32_t b) {
    return items[a].position[axis] < items[b].position[axis];
  });
  const uint32_t leftCount = regionCount / 2;
  const double leftCapacity = std::accumulate(capacities.begin() + firstRegion,
                                              capacities.begin() + firstRegion + leftCount, 0.0);
  const double allCapacity = std::accumulate(capacities.begin() + firstRegion,
                                             capacities.begin() + firstRegion + regionCount, 0.0);
  double total = 0.0;
  for (const uint32_t i : indices)
    total += items[i].weight;
  const double leftWeight = total * leftCapacity / allCapacity;
  size_t cut = 0;
  double accumulated = 0.0;
  while (cut < indices.size() && accumulated + 0.5 * items[indices[cut]].weight < leftWeight)
    accumulated += items[indices[cut++]].weight;
  std::vector<uint32_t> left(indices.begin(), indices.begin() + cut);
  std::vector<uint32_t> right(indices.begin() + cut, indices.end());
  bisect(items, std::move(left), capacities, firstRegion, leftCount, out);
  bisect(items, std::move(right), capacities, firstRegion + leftCount, regionCount - leftCount,
         out);
}

}  // namespace

std::vector<WorkItem> sampleBoxFaces(const std::vector<agent::BoxView>& boxes, double spacing,
                                     double groundZ, double groundClearance) {
  std::vector<WorkItem> out;
  for (const auto& box : boxes) {
    const Vec3 half = 0.5 * box.size;
    for (int axis = 0; axis < 3; ++axis)
      for (const double sign : {-1.0, 1.0}) {
        const Vec3 normal = sign * box.rotation.col(axis);
        const Vec3 faceCentre = box.center + half[axis] * normal;
        if (normal.z() < -0.7 && faceCentre.z() - groundZ < groundClearance) continue;
        const int u = (axis + 1) % 3, v = (axis + 2) % 3;
        const int nu = std::max(1, static_cast<int>(std::ceil(box.size[u] / spacing)));
        const int nv = std::max(1, static_cast<int>(std::ceil(box.size[v] / spacing)));
        const double weight = box.size[u] * box.size[v] / (nu * nv);
        for (int j = 0; j < nv; ++j)
          for (int i = 0; i < nu; ++i) {
            const double a = ((i + 0.5) / nu - 0.5) * box.size[u];
            const double b = ((j + 0.5) / nv - 0.5) * box.size[v];
            out.push_back(
                {faceCentre + a * box.rotation.col(u) + b * box.rotation.col(v), normal, weight});
          }
      }
  }
  return out;
}

std::vector<uint32_t> partitionWork(const std::vector<WorkItem>& items,
                                    const std::vector<double>& capacities) {
  COINSPECT_ASSERT(!capacities.empty());
  for (const double capacity : capacities)
    COINSPECT_ASSERT(capacity > 0.0);
  std::vector<uint32_t> out(items.size(), 0);
  std::vector<uint32_t> indices(items.size());
  std::iota(indices.begin(), indices.end(), 0u);
  bisect(items, std::move(indices), capacities, 0, static_cast<uint32_t>(capacities.size()), out);
  return out;
}

}  // namespace coinspect::strategies::coinspect_strategy
