// The message network: single-hop relay over the current topology, as the reference's ppcom
// router. A message is delivered at once into the receiver's inbox when sender and receiver are
// both alive and linked (and, with a bandwidth cap, the link has budget left); otherwise it is
// dropped and counted, never buffered.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "coinspect/comms/link_matrix.h"

namespace coinspect::comms {

// Bytes a message costs on a link besides its payload: from and to (4 + 4), sequence (8), send
// time (8) and a topic identifier (8). The topic text itself is not charged.
inline constexpr size_t kMessageHeaderBytes = 32;

struct Message {
  uint32_t from = 0;
  uint32_t to = 0;
  std::string topic;
  std::vector<uint8_t> payload;
  double sentTime = 0.0;  // simulated seconds
  uint64_t sequence = 0;  // assigned by Network::send: 0, 1, 2... in send order

  size_t sizeBytes() const { return kMessageHeaderBytes + payload.size(); }
};

// Counts of one directed link (sender -> receiver). sent = delivered + dropped.
struct LinkCounters {
  uint64_t sentMessages = 0;
  uint64_t sentBytes = 0;
  uint64_t deliveredMessages = 0;
  uint64_t deliveredBytes = 0;
  uint64_t droppedMessages = 0;
  uint64_t droppedBytes = 0;
  // Of the dropped ones, those refused by the bandwidth cap only (the link was up).
  uint64_t overBudgetMessages = 0;
  uint64_t overBudgetBytes = 0;

  LinkCounters& operator+=(const LinkCounters& other);
};

// Optional per-link bandwidth cap, as a token bucket per directed link: it holds at most
// bytesPerSecond * burstSeconds bytes, starts full and refills at bytesPerSecond in simulated
// time. A message larger than what the bucket holds at its send time is dropped (not queued:
// the reference never buffers, and a drop is what a strategy must cope with anyway).
struct BandwidthCap {
  double bytesPerSecond = 0.0;
  double burstSeconds = 1.0;
};

// Plain data with value semantics (copyable): the whole state of a run's network.
class Network {
 public:
  // Throws InputError when the cap is not finite and positive.
  explicit Network(size_t units, std::optional<BandwidthCap> cap = std::nullopt);

  size_t size() const { return units_; }
  // The links and who is alive from now on; `now` (simulated seconds, never decreasing) is the
  // time used by broadcast().
  void setTopology(const LinkMatrix& links, const std::vector<bool>& alive, double now);
  const LinkMatrix& links() const { return links_; }
  bool alive(uint32_t unit) const { return alive_[unit] != 0; }
  double now() const { return now_; }

  // True when delivered. from != to, both < size(), sentTime finite (caller's invariants).
  bool send(Message message);
  // Sends one copy to every current neighbour of `from` (increasing index), stamped now();
  // returns how many were delivered. Nothing is sent (or counted) when `from` has no neighbours.
  size_t broadcast(uint32_t from, const std::string& topic, const std::vector<uint8_t>& payload);

  // Delivered messages of `unit` in send order; empties the inbox.
  std::vector<Message> takeInbox(uint32_t unit);
  size_t inboxSize(uint32_t unit) const { return inboxes_[unit].size(); }

  const LinkCounters& counters(uint32_t from, uint32_t to) const;
  LinkCounters totals() const;

  // Called for every message sent (broadcast copies included) once its fate is decided, in send
  // order: the recorder logs traffic this way. It must not use the network; copied with it.
  using SendObserver = std::function<void(const Message& message, bool delivered)>;
  void setSendObserver(SendObserver observer) { sendObserver_ = std::move(observer); }

 private:
  bool withinBudget(size_t link, size_t bytes, double time);

  size_t units_;
  std::optional<BandwidthCap> cap_;
  LinkMatrix links_;
  std::vector<uint8_t> alive_;
  double now_ = 0.0;
  uint64_t nextSequence_ = 0;
  std::vector<std::vector<Message>> inboxes_;
  std::vector<LinkCounters> counters_;  // units_ * units_, row = sender
  std::vector<double> tokens_;          // bucket content per directed link, bytes
  std::vector<double> refilledAt_;      // time of the last refill per directed link
  SendObserver sendObserver_;
};

}  // namespace coinspect::comms
