#include "coinspect/strategies/coinspect/shared_progress.h"

#include <cstring>

namespace coinspect::strategies::coinspect_strategy {

std::vector<uint8_t> encodePatchKeys(const std::set<uint64_t>& keys) {
  std::vector<uint8_t> bytes(keys.size() * sizeof(uint64_t));
  size_t at = 0;
  for (const uint64_t key : keys) {
    std::memcpy(bytes.data() + at, &key, sizeof key);
    at += sizeof key;
  }
  return bytes;
}

std::optional<std::vector<uint64_t>> decodePatchKeys(const std::vector<uint8_t>& bytes) {
  if (bytes.size() % sizeof(uint64_t) != 0) return std::nullopt;
  std::vector<uint64_t> keys(bytes.size() / sizeof(uint64_t));
  if (!keys.empty()) std::memcpy(keys.data(), bytes.data(), bytes.size());
  return keys;
}

void SharedProgress::markViewed(uint64_t key) {
  if (known_.insert(key).second) sinceReport_.insert(key);
}

std::optional<agent::OutgoingMessage> SharedProgress::exchange(const agent::AgentView& view) {
  for (const auto& message : view.messages) {
    if (message.topic != kInspectedTopic) continue;
    if (const auto keys = decodePatchKeys(message.bytes))
      for (const uint64_t key : *keys)
        markViewed(key);  // relayed onwards with the next report
  }
  if (view.neighbours.empty() || view.time - lastReport_ < period_) return std::nullopt;
  const bool full = view.time - lastFull_ >= fullPeriod_;
  if (!full && sinceReport_.empty()) return std::nullopt;
  lastReport_ = view.time;
  if (full) lastFull_ = view.time;
  agent::OutgoingMessage out{"", kInspectedTopic, encodePatchKeys(full ? known_ : sinceReport_)};
  sinceReport_.clear();
  return out;
}

}  // namespace coinspect::strategies::coinspect_strategy
