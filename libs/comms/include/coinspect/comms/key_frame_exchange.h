// The reference's key-frame sharing: each new LiDAR key frame of a unit is received once by every
// neighbour in line of sight at the moment it is made, and never re-sent to units that come into
// sight later. Only ids travel here; the simulator keeps the key frames themselves.
#pragma once

#include <cstddef>
#include <cstdint>
#include <set>
#include <vector>

#include "coinspect/comms/link_matrix.h"

namespace coinspect::comms {

struct KeyFrameDelivery {
  uint32_t from = 0;
  uint32_t to = 0;
  uint64_t keyFrameId = 0;
  double time = 0.0;  // simulated seconds of publication
  bool operator==(const KeyFrameDelivery& other) const {
    return from == other.from && to == other.to && keyFrameId == other.keyFrameId &&
           time == other.time;
  }
};

// Copyable value type.
class KeyFrameExchange {
 public:
  explicit KeyFrameExchange(size_t units);

  // Delivers (unit, keyFrameId) to every neighbour of `unit` in `links` when both are alive;
  // returns the number of deliveries. A key frame id already published by this unit is ignored
  // (returns 0): each key frame goes out once.
  size_t publish(uint32_t unit, uint64_t keyFrameId, const LinkMatrix& links,
                 const std::vector<bool>& alive, double now);

  // Deliveries to `receiver` in publication order; empties its queue.
  std::vector<KeyFrameDelivery> takeDeliveries(uint32_t receiver);
  size_t deliveryCount() const { return deliveries_; }

 private:
  std::vector<std::set<uint64_t>> published_;
  std::vector<std::vector<KeyFrameDelivery>> pending_;
  size_t deliveries_ = 0;
};

}  // namespace coinspect::comms
