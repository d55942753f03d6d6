// OccupancyMap: construction, insertion of scans, merging, per-cell state.
#include "coinspect/mapping/occupancy_map.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <tuple>

#include <octomap/octomap_types.h>

#include "cell_blocks.h"
#include "coinspect/core/error.h"

namespace coinspect::mapping {

namespace {

inline Vec3 toVec3(const octomap::point3d& p) {
  return Vec3(p.x(), p.y(), p.z());
}

// Calls emit(morton) for each cell OctoMap's computeRayKeys(origin, end) lists, in its order:
// the cells a ray from `origin` crosses before the cell of `end`, the origin's first; false (and
// nothing emitted) when either point is outside the key range. The same Amanatides-Woo walk with
// the same arithmetic (float direction and length, double crossing distances, the same ties and
// the same stop when rounding overshoots the end cell), so every map stays cell for cell what
// computeRayKeys made of it; but it steps Morton codes in place, which the batch update needs,
// instead of filling a key list that was then converted key by key (OctoMap's walk alone was a
// tenth of a `slei-c` mission's time).
template <class Emit>
bool walkRay(const CellFrame& frame, const octomap::point3d& origin, const octomap::point3d& end,
             Emit&& emit) {
  CellKey fromKey, toKey;
  if (!frame.keyOf(toVec3(origin), fromKey) || !frame.keyOf(toVec3(end), toKey)) return false;
  if (fromKey == toKey) return true;
  uint64_t cell = mortonOf(fromKey);
  const uint64_t last = mortonOf(toKey);
  emit(cell);
  octomap::point3d direction = end - origin;  // OctoMap's float vector arithmetic, kept
  const float length = static_cast<float>(direction.norm());
  direction /= length;
  const double resolution = frame.resolution;
  int step[3];
  double crossing[3], spacing[3];  // distance along the ray to the next boundary, between them
  for (int i = 0; i < 3; ++i) {
    step[i] = direction(i) > 0.0f ? 1 : (direction(i) < 0.0f ? -1 : 0);
    if (step[i] == 0) {
      crossing[i] = spacing[i] = std::numeric_limits<double>::max();
      continue;
    }
    double border = frame.centreOf(fromKey[i]);
    border += static_cast<float>(step[i] * resolution * 0.5);
    crossing[i] = (border - origin(i)) / direction(i);
    spacing[i] = resolution / std::fabs(direction(i));
  }
  while (true) {
    const int axis = crossing[0] < crossing[1] ? (crossing[0] < crossing[2] ? 0 : 2)
                                               : (crossing[1] < crossing[2] ? 1 : 2);
    cell = stepMorton(cell, axis, step[axis]);
    crossing[axis] += spacing[axis];
    if (cell == last) return true;
    if (std::min(std::min(crossing[0], crossing[1]), crossing[2]) > length) return true;
    emit(cell);
  }
}

}  // namespace

OccupancyMap::OccupancyMap(const OccupancyMapOptions& options)
    : options_(options), cells_(std::make_unique<CellBlocks>(options.resolution)) {
  // Options come from code or from a strategy's validated config: bad values are bugs here.
  COINSPECT_ASSERT(options.resolution > 0.0 && std::isfinite(options.resolution));
  COINSPECT_ASSERT(options.maxRange > 0.0);
}

OccupancyMap::~OccupancyMap() = default;
OccupancyMap::OccupancyMap(OccupancyMap&&) noexcept = default;
OccupancyMap& OccupancyMap::operator=(OccupancyMap&&) noexcept = default;

void OccupancyMap::insertScan(const Vec3& origin, const std::vector<Eigen::Vector3f>& worldPoints) {
  ++revision_;
  scratch_.clear();
  collectScan(origin, worldPoints, scratch_, sortBuffer_);
  applyScratch(options_.raysClearOccupied);
}

OccupancyMap::ScanCells OccupancyMap::scanCells(
    const Vec3& origin, const std::vector<Eigen::Vector3f>& worldPoints) const {
  ScanCells cells{options_.resolution, options_.maxRange, {}};
  std::vector<uint64_t> buffer;
  collectScan(origin, worldPoints, cells.codes, buffer);
  sortUniqueCodes(cells.codes, buffer);
  cells.codes.shrink_to_fit();  // kept while other robots may apply them
  return cells;
}

void OccupancyMap::insertScanCells(const ScanCells& cells) {
  COINSPECT_ASSERT(cells.resolution == options_.resolution);
  COINSPECT_ASSERT(cells.maxRange == options_.maxRange);
  ++revision_;
  cells_->applySorted(cells.codes, options_.raysClearOccupied,
                      raysClearAt_ ? &raysClearAt_ : nullptr);
}

void OccupancyMap::collectScan(const Vec3& origin, const std::vector<Eigen::Vector3f>& worldPoints,
                               std::vector<uint64_t>& codes,
                               std::vector<uint64_t>& sortBuffer) const {
  const CellFrame& frame = cells_->frame();
  const octomap::point3d sensor(static_cast<float>(origin.x()), static_cast<float>(origin.y()),
                                static_cast<float>(origin.z()));
  CellKey key;
  COINSPECT_ASSERT(frame.keyOf(origin, key));

  // 1. The end cell of every ray: the return's cell (occupied) or, for a return beyond the range
  // cap, the cell at the cap (free space only). Rays to the same end cell clear the same cells
  // once cast to its centre (OctoMap's `discretize`), so the distinct end cells are cast only.
  std::vector<uint64_t> ends;
  ends.reserve(worldPoints.size());
  for (const auto& p : worldPoints) {
    COINSPECT_ASSERT(p.allFinite());
    const Vec3 offset = p.cast<double>() - origin;
    const double range = offset.norm();
    const bool capped = range > options_.maxRange;
    const Vec3 end =
        capped ? Vec3(origin + offset * (options_.maxRange / range)) : p.cast<double>();
    if (!frame.keyOf(end, key)) continue;  // beyond the key range
    ends.push_back(updateCode(key, !capped));
  }
  sortUniqueCodes(ends, sortBuffer);

  // 2. Free cells along every distinct ray (the end cell excluded), then the occupied ends. Rays
  // from one origin share most cells near it: a direct-mapped table of recent codes drops most
  // repeats before the sort (exact repeats only, so the result is the same, just cheaper).
  constexpr int kFilterBits = 13;
  thread_local std::vector<uint64_t> recent;
  recent.assign(size_t{1} << kFilterBits, ~uint64_t{0});
  for (const uint64_t end : ends) {
    const Eigen::Vector3f c = frame.floatCentreOf(keyOfMorton(end >> 1));
    const octomap::point3d endCentre(c.x(), c.y(), c.z());
    walkRay(frame, sensor, endCentre, [&](uint64_t morton) {
      const uint64_t code = morton << 1;  // free
      uint64_t& slot = recent[(code * 0x9E3779B97F4A7C15ULL) >> (64 - kFilterBits)];
      if (slot == code) return;
      slot = code;
      codes.push_back(code);
    });
    if (end & 1U) codes.push_back(end);
  }
}

void OccupancyMap::merge(const OccupancyMap& other) {
  COINSPECT_ASSERT(other.options_.resolution == options_.resolution);
  ++revision_;
  std::vector<uint64_t> codes, buffer;  // not scratch_: `other` may be this map
  codes.reserve(other.cells_->knownCells());
  other.cells_->appendCodes(codes);
  sortUniqueCodes(codes, buffer);  // one code per cell already: this only sorts
  cells_->applySorted(codes, options_.raysClearOccupied, raysClearAt_ ? &raysClearAt_ : nullptr);
}

void OccupancyMap::observeCells(const std::vector<Vec3>& freePoints,
                                const std::vector<Vec3>& occupiedPoints) {
  ++revision_;
  scratch_.clear();
  CellKey key;
  for (const auto& p : freePoints)
    if (cells_->frame().keyOf(p, key)) scratch_.push_back(updateCode(key, false));
  for (const auto& p : occupiedPoints)
    if (cells_->frame().keyOf(p, key)) scratch_.push_back(updateCode(key, true));
  applyScratch(true);
}

void OccupancyMap::applyScratch(bool missesClearOccupied) {
  sortUniqueCodes(scratch_, sortBuffer_);
  cells_->applySorted(scratch_, missesClearOccupied, raysClearAt_ ? &raysClearAt_ : nullptr);
}

CellState OccupancyMap::state(const Vec3& point) const {
  CellKey key;
  if (!cells_->frame().keyOf(point, key)) return CellState::Unknown;
  const float value = cells_->logOdds(key);
  if (value == CellBlocks::kUnknown) return CellState::Unknown;
  return cells_->frame().occupied(value) ? CellState::Occupied : CellState::Free;
}

Vec3 OccupancyMap::cellCentre(const Vec3& point) const {
  CellKey key;
  COINSPECT_ASSERT(cells_->frame().keyOf(point, key));
  return cells_->frame().centreOf(key);
}

std::optional<std::pair<Vec3, Vec3>> OccupancyMap::takeChangedCentres() {
  const CellBlocks::KeyBox keys = cells_->takeChangedKeys();
  if (keys.empty()) return std::nullopt;
  const auto centre = [&](const std::array<int, 3>& k) {
    return cells_->frame().centreOf(CellKey{
        static_cast<uint16_t>(k[0]), static_cast<uint16_t>(k[1]), static_cast<uint16_t>(k[2])});
  };
  return std::make_pair(centre(keys.low), centre(keys.high));
}

size_t OccupancyMap::occupiedCount() const {
  return cells_->occupiedCells();
}

size_t OccupancyMap::knownCount() const {
  return cells_->knownCells();
}

float OccupancyMap::hitLogOdds() const {
  return cells_->frame().hitLog;
}

float OccupancyMap::missLogOdds() const {
  return cells_->frame().missLog;
}

std::vector<OccupancyMap::KnownCell> OccupancyMap::knownCells() const {
  std::vector<KnownCell> out;
  out.reserve(cells_->knownCells());
  for (const auto& block : cells_->blocks())
    for (unsigned i = 0; i < CellBlocks::kBlockCells; ++i) {
      const float value = block->logOdds[i];
      if (value == CellBlocks::kUnknown) continue;
      const CellKey key = CellBlocks::keyInBlock(*block, i);
      out.push_back({{key[0], key[1], key[2]},
                     cells_->frame().centreOf(key),
                     value,
                     cells_->frame().occupied(value)});
    }
  std::sort(out.begin(), out.end(), [](const KnownCell& a, const KnownCell& b) {
    return std::tie(a.key[2], a.key[1], a.key[0]) < std::tie(b.key[2], b.key[1], b.key[0]);
  });
  return out;
}

}  // namespace coinspect::mapping
