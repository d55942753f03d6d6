// Store-and-forward of LiDAR key frames between robots. In CARIC a neighbour's key frame arrives
// once, only if the two are in line of sight at that moment, and is never sent again: a
// photographer that was behind a tower when the explorer mapped it never learns that part of the
// structure. Each robot therefore keeps every key frame it got (its own, the simulator's, relayed
// ones) and gossips them (anti-entropy): every `digestPeriod` it broadcasts which frames it holds
// (id ranges per producer, a few bytes); a neighbour that holds frames missing from a digest sends
// them straight to its author, at most `framesPerReply` per digest. Frames travel as messages,
// points quantised to 1 cm around the scan position. Points of UAVs in sight (rotors, bodies) are
// removed when a robot first gets a frame, so relayed frames carry no phantom obstacles. Robots
// that receive a frame as the same bytes hold one decoded copy (memory: a fleet of 48 kept one
// each).
#pragma once

#include <cstdint>
#include <deque>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "coinspect/agent/agent_view.h"
#include "coinspect/agent/commands.h"

namespace coinspect::strategies::coinspect_strategy {

struct RelayOptions {
  double digestPeriod = 2.0;   // s between digests
  size_t framesPerReply = 24;  // frames sent in answer to one digest
};

inline constexpr const char* kDigestTopic = "coinspect/kf-digest";
inline constexpr const char* kFrameTopic = "coinspect/kf";

// Wire format of one key frame (exposed for tests). `producer` is a fleet index.
std::vector<uint8_t> encodeKeyFrame(const agent::KeyFrame& frame, uint16_t producer);
// Nothing for a malformed message (wrong size, bad producer, out-of-range values).
std::optional<agent::KeyFrame> decodeKeyFrame(const std::vector<uint8_t>& bytes,
                                              const std::vector<std::string>& fleet);

// Frames known per producer (fleet index) as sorted, disjoint, inclusive id ranges.
using IdRanges = std::map<uint16_t, std::vector<std::pair<uint64_t, uint64_t>>>;
std::vector<uint8_t> encodeDigest(const IdRanges& ranges);
std::optional<IdRanges> decodeDigest(const std::vector<uint8_t>& bytes, size_t fleetSize);

class KeyFrameRelay {
 public:
  // `fleet`: every unit's name in fleet order (producers travel as fleet indices).
  KeyFrameRelay(const RelayOptions& options, std::vector<std::string> fleet);

  // Takes the decision's new own and received key frames (filtering UAV points) and the relayed
  // frames and digests among its messages; returns the messages to send now.
  std::vector<agent::OutgoingMessage> exchange(const agent::AgentView& view);
  // Frames new to this robot since the last call, oldest first, at most `max` (the rest wait,
  // so a burst of relayed frames does not stall one decision).
  std::vector<agent::KeyFrameView> takeNew(size_t max);

  size_t known() const { return frames_.size(); }
  size_t relayedIn() const { return relayedIn_; }

 private:
  bool add(agent::KeyFrameView frame, uint16_t producer);
  IdRanges ranges() const;

  RelayOptions options_;
  std::vector<std::string> fleet_;
  using Frames = std::map<std::pair<uint16_t, uint64_t>, agent::KeyFrameView>;
  Frames frames_;  // by (producer's fleet index, id)
  std::deque<agent::KeyFrameView> fresh_;
  double lastDigest_ = -1e300;
  size_t relayedIn_ = 0;
};

}  // namespace coinspect::strategies::coinspect_strategy
