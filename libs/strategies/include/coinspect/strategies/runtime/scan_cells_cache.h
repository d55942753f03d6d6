// The cells a key frame observes, found once for every robot that inserts it. In a relaying
// fleet each frame reaches most robots (75 robots on `slei-a`: 44 insertions per frame), and
// casting its rays was a fifth of such a mission's time; a robot's map only applies the cells.
// Frames are keyed by their object: robots that received the same bytes share one decoded frame
// (the key-frame relay interns them), so a hit needs no comparison of points.
#pragma once

#include <cstddef>
#include <list>
#include <memory>
#include <mutex>
#include <unordered_map>

#include "coinspect/agent/observations.h"
#include "coinspect/mapping/occupancy_map.h"

namespace coinspect::strategies::runtime {

class ScanCellsCache {
 public:
  using Cells = std::shared_ptr<const mapping::OccupancyMap::ScanCells>;

  // Keeps the cells of at most `capacity` frames, the least recently used leaving first (a frame
  // reaches the robots of a meeting within seconds, but the relay keeps every frame for the whole
  // mission: holding the cells as long would cost more memory than the frames themselves).
  explicit ScanCellsCache(size_t capacity);

  // The cells `frame` observes in a map of `map`'s resolution and range cap: found now, or by an
  // earlier call for the same frame object and options (the same cells either way). Thread-safe.
  Cells cellsOf(const agent::KeyFrameView& frame, const mapping::OccupancyMap& map);

  // The process's cache, used by RobotMap::insertFrame.
  static ScanCellsCache& shared();

 private:
  struct Key {
    const agent::KeyFrame* frame;
    double resolution;
    double maxRange;
    bool operator==(const Key& other) const {
      return frame == other.frame && resolution == other.resolution && maxRange == other.maxRange;
    }
  };
  struct KeyHash {
    size_t operator()(const Key& key) const;
  };
  struct Entry {
    Key key;
    // The address alone could be a later frame's once this one is freed: a hit must still hold.
    std::weak_ptr<const agent::KeyFrame> frame;
    Cells cells;
  };

  size_t capacity_;
  std::mutex mutex_;
  std::list<Entry> recent_;  // most recently used first
  std::unordered_map<Key, std::list<Entry>::iterator, KeyHash> index_;
};

}  // namespace coinspect::strategies::runtime
