// What the fleet has inspected, as far as this robot knows: the keys of the surface patches it
// viewed itself and those its neighbours reported. Robots broadcast the keys they learnt since
// their last report every `period` seconds and everything they know every `fullPeriod` seconds
// (a neighbour out of sight at the time of a report catches up later). Patch keys are
// positions on a fixed grid (planning/coverage.h), so every robot names a patch the same way.
// A robot whose own region is finished uses this to help with the rest without repeating work,
// which also takes over the region of a robot that failed.
#pragma once

#include <cstdint>
#include <optional>
#include <set>
#include <vector>

#include "coinspect/agent/agent_view.h"
#include "coinspect/agent/commands.h"

namespace coinspect::strategies::coinspect_strategy {

inline constexpr const char* kInspectedTopic = "coinspect/inspected";

std::vector<uint8_t> encodePatchKeys(const std::set<uint64_t>& keys);
// Nothing for a malformed message (size not a multiple of 8).
std::optional<std::vector<uint64_t>> decodePatchKeys(const std::vector<uint8_t>& bytes);

class SharedProgress {
 public:
  explicit SharedProgress(double period = 3.0, double fullPeriod = 30.0)
      : period_(period), fullPeriod_(fullPeriod) {}

  void markViewed(uint64_t key);
  bool done(uint64_t key) const { return known_.count(key) != 0; }
  size_t knownCount() const { return known_.size(); }

  // Reads reports among the view's messages; returns the report to send now, if any.
  std::optional<agent::OutgoingMessage> exchange(const agent::AgentView& view);

 private:
  double period_, fullPeriod_;
  std::set<uint64_t> known_;
  std::set<uint64_t> sinceReport_;
  double lastReport_ = -1e300, lastFull_ = -1e300;
};

}  // namespace coinspect::strategies::coinspect_strategy
