// Store and forward (SLEI3D, doc/features.md): data that robots carry and hand over when they
// meet. Each unit holds a set of items (inspection results, by feature index); at every
// topology update each alive unit takes the items its alive neighbours held before the update.
// One hop per update, from a snapshot, so the outcome does not depend on the unit order and data
// crosses a chain of linked units one link per update (every 20 ms at 50 Hz).
#pragma once

#include <cstdint>
#include <utility>
#include <vector>

#include "coinspect/comms/link_matrix.h"

namespace coinspect::comms {

// One item arriving at one unit.
struct Handover {
  uint32_t unit = 0;  // the receiver
  uint32_t item = 0;
  uint32_t from = 0;  // the lowest-indexed neighbour that held it
};

// Copyable value type.
class CarriedData {
 public:
  CarriedData(size_t units, size_t items);

  size_t units() const { return units_; }
  size_t items() const { return items_; }
  bool holds(uint32_t unit, uint32_t item) const;
  size_t heldCount(uint32_t unit) const;
  // The unit gets an item by itself (it inspected the feature); false if it already held it.
  bool add(uint32_t unit, uint32_t item);
  // A dead unit's items are gone: nobody can read them any more.
  void drop(uint32_t unit);
  // One exchange over `links` between alive units; returns what changed hands, by receiver
  // then item (ascending).
  std::vector<Handover> exchange(const LinkMatrix& links, const std::vector<bool>& alive);

 private:
  size_t units_, items_;
  std::vector<uint8_t> held_;  // units_ x items_
  std::vector<size_t> counts_;
};

// Meetings: a pair of units meets when its link comes up after being down for at least `gap`
// seconds (a link that flickers at the edge of range is one meeting). Pairs linked at the first
// update are where the fleet starts, not meetings.
class MeetingCounter {
 public:
  MeetingCounter(size_t units, double gap);
  // Returns the pairs (a < b) whose meeting starts at this update.
  std::vector<std::pair<uint32_t, uint32_t>> update(double time, const LinkMatrix& links);

 private:
  size_t units_;
  double gap_;
  bool first_ = true;
  LinkMatrix previous_;            // the links at the previous update
  std::vector<double> lostSince_;  // per pair (a * units + b): when its link went down
};

}  // namespace coinspect::comms
