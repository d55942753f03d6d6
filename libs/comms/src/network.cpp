#include "coinspect/comms/network.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "coinspect/core/error.h"

namespace coinspect::comms {

LinkCounters& LinkCounters::operator+=(const LinkCounters& other) {
  sentMessages += other.sentMessages;
  sentBytes += other.sentBytes;
  deliveredMessages += other.deliveredMessages;
  deliveredBytes += other.deliveredBytes;
  droppedMessages += other.droppedMessages;
  droppedBytes += other.droppedBytes;
  overBudgetMessages += other.overBudgetMessages;
  overBudgetBytes += other.overBudgetBytes;
  return *this;
}

Network::Network(size_t units, std::optional<BandwidthCap> cap)
    : units_(units),
      cap_(cap),
      links_(units),
      alive_(units, 1),
      inboxes_(units),
      counters_(units * units) {
  if (cap_) {
    if (!(std::isfinite(cap_->bytesPerSecond) && cap_->bytesPerSecond > 0.0))
      throw InputError("network", "bandwidth cap",
                       "must be a finite positive number of bytes per second, got " +
                           std::to_string(cap_->bytesPerSecond));
    if (!(std::isfinite(cap_->burstSeconds) && cap_->burstSeconds > 0.0))
      throw InputError(
          "network", "bandwidth burst",
          "must be a finite positive number of seconds, got " + std::to_string(cap_->burstSeconds));
    tokens_.assign(units * units, cap_->bytesPerSecond * cap_->burstSeconds);
    refilledAt_.assign(units * units, 0.0);
  }
}

void Network::setTopology(const LinkMatrix& links, const std::vector<bool>& alive, double now) {
  COINSPECT_ASSERT(links.size() == units_ && alive.size() == units_);
  COINSPECT_ASSERT(std::isfinite(now) && now >= now_);
  links_ = links;
  for (size_t i = 0; i < units_; ++i)
    alive_[i] = alive[i] ? 1 : 0;
  now_ = now;
}

bool Network::withinBudget(size_t link, size_t bytes, double time) {
  if (!cap_) return true;
  const double capacity = cap_->bytesPerSecond * cap_->burstSeconds;
  // Time only moves forward for a bucket, so a message stamped in the past does not refill it.
  if (time > refilledAt_[link]) {
    tokens_[link] =
        std::min(capacity, tokens_[link] + (time - refilledAt_[link]) * cap_->bytesPerSecond);
    refilledAt_[link] = time;
  }
  if (static_cast<double>(bytes) > tokens_[link]) return false;
  tokens_[link] -= static_cast<double>(bytes);
  return true;
}

bool Network::send(Message message) {
  COINSPECT_ASSERT(message.from < units_ && message.to < units_ && message.from != message.to);
  COINSPECT_ASSERT(std::isfinite(message.sentTime));
  message.sequence = nextSequence_++;
  const size_t link = message.from * units_ + message.to;
  const size_t bytes = message.sizeBytes();
  LinkCounters& counters = counters_[link];
  counters.sentMessages += 1;
  counters.sentBytes += bytes;
  const bool up = alive_[message.from] != 0 && alive_[message.to] != 0 &&
                  links_.linked(message.from, message.to);
  const bool delivered = up && withinBudget(link, bytes, message.sentTime);
  if (sendObserver_) sendObserver_(message, delivered);
  if (!delivered) {
    counters.droppedMessages += 1;
    counters.droppedBytes += bytes;
    if (up) {
      counters.overBudgetMessages += 1;
      counters.overBudgetBytes += bytes;
    }
    return false;
  }
  counters.deliveredMessages += 1;
  counters.deliveredBytes += bytes;
  inboxes_[message.to].push_back(std::move(message));
  return true;
}

size_t Network::broadcast(uint32_t from, const std::string& topic,
                          const std::vector<uint8_t>& payload) {
  COINSPECT_ASSERT(from < units_);
  size_t delivered = 0;
  for (uint32_t to : links_.neighbours(from)) {
    Message message;
    message.from = from;
    message.to = to;
    message.topic = topic;
    message.payload = payload;
    message.sentTime = now_;
    delivered += send(std::move(message)) ? 1 : 0;
  }
  return delivered;
}

std::vector<Message> Network::takeInbox(uint32_t unit) {
  COINSPECT_ASSERT(unit < units_);
  std::vector<Message> taken;
  taken.swap(inboxes_[unit]);
  return taken;
}

const LinkCounters& Network::counters(uint32_t from, uint32_t to) const {
  COINSPECT_ASSERT(from < units_ && to < units_);
  return counters_[from * units_ + to];
}

LinkCounters Network::totals() const {
  LinkCounters sum;
  for (const LinkCounters& c : counters_)
    sum += c;
  return sum;
}

}  // namespace coinspect::comms
