#include "coinspect/strategies/star/star_inspect.h"

#include <algorithm>
#include <limits>

namespace coinspect::strategies::star {

namespace {
constexpr double kFaceSpacing = 4.0;  // m between samples of the box faces
}

SurfaceSplit::SurfaceSplit(const std::vector<agent::BoxView>& boxes, double groundZ, size_t parts)
    : parts_(std::max<size_t>(1, parts)) {
  items_ = coinspect_strategy::sampleBoxFaces(boxes, kFaceSpacing, groundZ, 1.0);
  region_ = coinspect_strategy::partitionWork(items_, std::vector<double>(parts_, 1.0));
}

uint32_t SurfaceSplit::ownerOf(const Vec3& point) const {
  size_t best = 0;
  double bestDistance = std::numeric_limits<double>::infinity();
  for (size_t i = 0; i < items_.size(); ++i) {
    const double d = (items_[i].position - point).squaredNorm();
    if (d < bestDistance) bestDistance = d, best = i;
  }
  return items_.empty() ? 0u : region_[best];
}

std::optional<Vec3> SurfaceSplit::standoffPoint(uint32_t part, const Vec3& near,
                                                double standoff) const {
  std::optional<Vec3> best;
  double bestDistance = std::numeric_limits<double>::infinity();
  for (size_t i = 0; i < items_.size(); ++i) {
    if (region_[i] != part) continue;
    const Vec3 p = items_[i].position + standoff * items_[i].normal;
    const double d = (p - near).norm();
    if (d < bestDistance) bestDistance = d, best = p;
  }
  return best;
}

std::vector<uint8_t> encodeKeys(std::vector<uint64_t> keys) {
  std::sort(keys.begin(), keys.end());
  keys.erase(std::unique(keys.begin(), keys.end()), keys.end());
  std::vector<uint8_t> bytes;
  uint64_t previous = 0;
  for (const uint64_t key : keys) {
    uint64_t delta = key - previous;
    previous = key;
    do {
      const uint8_t low = delta & 0x7f;
      delta >>= 7;
      bytes.push_back(delta ? (low | 0x80) : low);
    } while (delta);
  }
  return bytes;
}

bool decodeKeys(const std::vector<uint8_t>& bytes, std::vector<uint64_t>* out) {
  std::vector<uint64_t> keys;
  uint64_t previous = 0, delta = 0;
  int shift = 0;
  for (const uint8_t byte : bytes) {
    if (shift > 63) return false;
    delta |= static_cast<uint64_t>(byte & 0x7f) << shift;
    if (byte & 0x80) {
      shift += 7;
      continue;
    }
    previous += delta;
    keys.push_back(previous);
    delta = 0;
    shift = 0;
  }
  if (shift != 0) return false;  // a truncated varint
  *out = std::move(keys);
  return true;
}

std::vector<planning::InspectionPatch> dropInspected(
    const std::vector<planning::InspectionPatch>& patches, const std::set<uint64_t>& inspected) {
  std::vector<planning::InspectionPatch> out;
  for (const auto& patch : patches)
    if (!inspected.count(patch.key)) out.push_back(patch);
  return out;
}

std::vector<std::vector<size_t>> clusterViews(const std::vector<Vec3>& cameras, double radius,
                                              const mapping::VoxelGrid* grid) {
  std::vector<std::vector<size_t>> clusters;
  for (size_t i = 0; i < cameras.size(); ++i) {
    bool joined = false;
    for (auto& cluster : clusters) {
      const Vec3& seed = cameras[cluster.front()];
      if ((cameras[i] - seed).norm() > radius) continue;
      if (grid && !planning::freeLineOfSight(*grid, seed, cameras[i])) continue;
      cluster.push_back(i);
      joined = true;
      break;
    }
    if (!joined) clusters.push_back({i});
  }
  return clusters;
}

}  // namespace coinspect::strategies::star
