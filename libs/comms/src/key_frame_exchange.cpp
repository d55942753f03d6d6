#include "coinspect/comms/key_frame_exchange.h"

#include <utility>

#include "coinspect/core/error.h"

namespace coinspect::comms {

KeyFrameExchange::KeyFrameExchange(size_t units) : published_(units), pending_(units) {}

size_t KeyFrameExchange::publish(uint32_t unit, uint64_t keyFrameId, const LinkMatrix& links,
                                 const std::vector<bool>& alive, double now) {
  COINSPECT_ASSERT(unit < published_.size());
  COINSPECT_ASSERT(links.size() == published_.size() && alive.size() == published_.size());
  if (!published_[unit].insert(keyFrameId).second) return 0;
  if (!alive[unit]) return 0;
  size_t count = 0;
  for (uint32_t to : links.neighbours(unit)) {
    if (!alive[to]) continue;
    pending_[to].push_back({unit, to, keyFrameId, now});
    ++count;
  }
  deliveries_ += count;
  return count;
}

std::vector<KeyFrameDelivery> KeyFrameExchange::takeDeliveries(uint32_t receiver) {
  COINSPECT_ASSERT(receiver < pending_.size());
  std::vector<KeyFrameDelivery> taken;
  taken.swap(pending_[receiver]);
  return taken;
}

}  // namespace coinspect::comms
