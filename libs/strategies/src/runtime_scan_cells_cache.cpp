#include "coinspect/strategies/runtime/scan_cells_cache.h"

#include <functional>

#include "coinspect/core/error.h"

namespace coinspect::strategies::runtime {

namespace {
// 1024 frames: the 75-robot `slei-a` mission's insertions found 93 % of their frames among the
// last 1024 inserted (88 % among 256); full, the cache added 0.12 GB to that mission's 0.95 GB.
constexpr size_t kSharedCapacity = 1024;
}  // namespace

size_t ScanCellsCache::KeyHash::operator()(const Key& key) const {
  const size_t h = std::hash<const void*>()(key.frame);
  return h ^ (std::hash<double>()(key.resolution) * 31) ^ (std::hash<double>()(key.maxRange) * 131);
}

ScanCellsCache::ScanCellsCache(size_t capacity) : capacity_(capacity) {
  COINSPECT_ASSERT(capacity > 0);
}

ScanCellsCache::Cells ScanCellsCache::cellsOf(const agent::KeyFrameView& frame,
                                              const mapping::OccupancyMap& map) {
  COINSPECT_ASSERT(frame);
  const Key key{frame.get(), map.options().resolution, map.options().maxRange};
  {
    const std::lock_guard<std::mutex> lock(mutex_);
    const auto found = index_.find(key);
    if (found != index_.end()) {
      if (found->second->frame.lock() == frame) {
        recent_.splice(recent_.begin(), recent_, found->second);
        return found->second->cells;
      }
      recent_.erase(found->second);  // a freed frame's address, now another's
      index_.erase(found);
    }
  }
  // Found outside the lock: another thread may find the same cells meanwhile (equal ones).
  auto cells = std::make_shared<const mapping::OccupancyMap::ScanCells>(
      map.scanCells(frame->position, frame->points));
  const std::lock_guard<std::mutex> lock(mutex_);
  if (index_.count(key)) return cells;  // the other thread's entry stays
  recent_.push_front(Entry{key, frame, cells});
  index_.emplace(key, recent_.begin());
  if (recent_.size() > capacity_) {
    index_.erase(recent_.back().key);
    recent_.pop_back();
  }
  return cells;
}

ScanCellsCache& ScanCellsCache::shared() {
  static ScanCellsCache cache(kSharedCapacity);
  return cache;
}

}  // namespace coinspect::strategies::runtime
