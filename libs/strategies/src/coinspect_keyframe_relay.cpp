#include "coinspect/strategies/coinspect/keyframe_relay.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <memory>
#include <mutex>
#include <unordered_map>

#include "coinspect/core/hash.h"
#include "coinspect/strategies/runtime/robot_map.h"

namespace coinspect::strategies::coinspect_strategy {

namespace {

constexpr double kQuantum = 0.01;  // m per unit of a relayed point's offset from the scan position

class Writer {
 public:
  template <typename T>
  void put(T value) {
    const size_t at = bytes.size();
    bytes.resize(at + sizeof(T));
    std::memcpy(bytes.data() + at, &value, sizeof(T));
  }
  std::vector<uint8_t> bytes;
};

class Reader {
 public:
  explicit Reader(const std::vector<uint8_t>& bytes) : bytes_(bytes) {}
  template <typename T>
  bool get(T* value) {
    if (bytes_.size() - at_ < sizeof(T)) return false;
    std::memcpy(value, bytes_.data() + at_, sizeof(T));
    at_ += sizeof(T);
    return true;
  }
  size_t left() const { return bytes_.size() - at_; }

 private:
  const std::vector<uint8_t>& bytes_;
  size_t at_ = 0;
};

bool finite(const agent::Vec3& v) {
  return v.allFinite();
}

bool sameFrame(const agent::KeyFrame& a, const agent::KeyFrame& b) {
  return a.producer == b.producer && a.id == b.id && a.time == b.time && a.position == b.position &&
         a.bodyOrientation.coeffs() == b.bodyOrientation.coeffs() && a.points == b.points;
}

// Relayed frames decoded by every robot of the process, by a hash of their message: a frame
// relayed through a fleet arrives at each robot as the same bytes, and each kept its own decoded
// copy (slei-d, 48 UAVs: 1.5 GB of 4.3 GB after 1200 s, and growing). A robot gets the frame
// another robot decoded only when it equals its own decoding (frames of one producer and id
// relayed by different robots may differ: each robot that got it from the simulator dropped the
// UAV points it saw), so nothing a robot holds depends on what the others received. Entries are
// weak: a frame lives as long as a robot holds it.
class DecodedFrames {
 public:
  agent::KeyFrameView intern(const std::vector<uint8_t>& bytes, agent::KeyFrame decoded) {
    const uint64_t hash = core::fnv1a(bytes.data(), bytes.size());
    const std::lock_guard<std::mutex> lock(mutex_);
    auto& bucket = frames_[hash];
    bucket.erase(std::remove_if(bucket.begin(), bucket.end(),
                                [](const auto& weak) { return weak.expired(); }),
                 bucket.end());
    for (const auto& weak : bucket)
      if (auto held = weak.lock(); held && sameFrame(*held, decoded)) return held;
    auto frame = std::make_shared<const agent::KeyFrame>(std::move(decoded));
    bucket.push_back(frame);
    return frame;
  }

 private:
  std::mutex mutex_;
  std::unordered_map<uint64_t, std::vector<std::weak_ptr<const agent::KeyFrame>>> frames_;
};

DecodedFrames& decodedFrames() {
  static DecodedFrames frames;
  return frames;
}

}  // namespace

std::vector<uint8_t> encodeKeyFrame(const agent::KeyFrame& frame, uint16_t producer) {
  Writer w;
  w.put(producer);
  w.put(frame.id);
  w.put(frame.time);
  for (int i = 0; i < 3; ++i)
    w.put(frame.position[i]);
  const auto& q = frame.bodyOrientation;
  for (const double c : {q.w(), q.x(), q.y(), q.z()})
    w.put(c);
  std::vector<std::array<int16_t, 3>> kept;
  kept.reserve(frame.points.size());
  for (const auto& point : frame.points) {
    const agent::Vec3 offset = (point.cast<double>() - frame.position) / kQuantum;
    if (!(offset.cwiseAbs().maxCoeff() < 32767.0)) continue;  // beyond 327 m: no LiDAR of ours
    kept.push_back({static_cast<int16_t>(std::lround(offset.x())),
                    static_cast<int16_t>(std::lround(offset.y())),
                    static_cast<int16_t>(std::lround(offset.z()))});
  }
  w.put(static_cast<uint32_t>(kept.size()));
  for (const auto& p : kept)
    for (const int16_t c : p)
      w.put(c);
  return std::move(w.bytes);
}

std::optional<agent::KeyFrame> decodeKeyFrame(const std::vector<uint8_t>& bytes,
                                              const std::vector<std::string>& fleet) {
  Reader r(bytes);
  agent::KeyFrame frame;
  uint16_t producer = 0;
  double q[4];
  uint32_t count = 0;
  if (!r.get(&producer) || !r.get(&frame.id) || !r.get(&frame.time)) return std::nullopt;
  for (int i = 0; i < 3; ++i)
    if (!r.get(&frame.position[i])) return std::nullopt;
  for (double& c : q)
    if (!r.get(&c)) return std::nullopt;
  if (!r.get(&count) || r.left() != size_t{count} * 3 * sizeof(int16_t)) return std::nullopt;
  if (producer >= fleet.size() || !std::isfinite(frame.time) || !finite(frame.position))
    return std::nullopt;
  frame.producer = fleet[producer];
  frame.bodyOrientation = Eigen::Quaterniond(q[0], q[1], q[2], q[3]);
  if (!frame.bodyOrientation.coeffs().allFinite()) return std::nullopt;
  frame.points.reserve(count);
  for (uint32_t i = 0; i < count; ++i) {
    int16_t c[3] = {0, 0, 0};
    for (int16_t& v : c)
      r.get(&v);
    frame.points.push_back(
        (frame.position + kQuantum * agent::Vec3(c[0], c[1], c[2])).cast<float>());
  }
  return frame;
}

std::vector<uint8_t> encodeDigest(const IdRanges& ranges) {
  Writer w;
  w.put(static_cast<uint16_t>(ranges.size()));
  for (const auto& [producer, list] : ranges) {
    w.put(producer);
    w.put(static_cast<uint32_t>(list.size()));
    for (const auto& [first, last] : list) {
      w.put(first);
      w.put(last);
    }
  }
  return std::move(w.bytes);
}

std::optional<IdRanges> decodeDigest(const std::vector<uint8_t>& bytes, size_t fleetSize) {
  Reader r(bytes);
  IdRanges ranges;
  uint16_t producers = 0;
  if (!r.get(&producers)) return std::nullopt;
  for (uint16_t p = 0; p < producers; ++p) {
    uint16_t producer = 0;
    uint32_t count = 0;
    if (!r.get(&producer) || !r.get(&count) || producer >= fleetSize) return std::nullopt;
    if (r.left() < size_t{count} * 2 * sizeof(uint64_t)) return std::nullopt;
    auto& list = ranges[producer];
    for (uint32_t i = 0; i < count; ++i) {
      uint64_t first = 0, last = 0;
      r.get(&first);
      r.get(&last);
      if (last < first) return std::nullopt;
      list.emplace_back(first, last);
    }
  }
  if (r.left() != 0) return std::nullopt;
  return ranges;
}

KeyFrameRelay::KeyFrameRelay(const RelayOptions& options, std::vector<std::string> fleet)
    : options_(options), fleet_(std::move(fleet)) {}

bool KeyFrameRelay::add(agent::KeyFrameView frame, uint16_t producer) {
  const auto [it, inserted] = frames_.emplace(std::make_pair(producer, frame->id), frame);
  if (inserted) fresh_.push_back(std::move(frame));
  return inserted;
}

IdRanges KeyFrameRelay::ranges() const {
  IdRanges out;
  for (const auto& [key, frame] : frames_) {
    auto& list = out[key.first];
    if (!list.empty() && list.back().second + 1 == key.second)
      list.back().second = key.second;
    else
      list.emplace_back(key.second, key.second);
  }
  return out;
}

std::vector<agent::OutgoingMessage> KeyFrameRelay::exchange(const agent::AgentView& view) {
  const auto producerIndex = [&](const std::string& name) -> std::optional<uint16_t> {
    const auto it = std::find(fleet_.begin(), fleet_.end(), name);
    if (it == fleet_.end()) return std::nullopt;
    return static_cast<uint16_t>(it - fleet_.begin());
  };
  // Frames straight from the simulator: drop the points of UAVs in sight now (the scan is
  // fresh), once, so every later holder inserts the cleaned frame.
  const auto uavs = runtime::uavPositions(view);
  for (const auto* frames : {&view.ownKeyFrames, &view.receivedKeyFrames})
    for (const auto& frame : *frames) {
      const auto producer = frame ? producerIndex(frame->producer) : std::nullopt;
      if (!producer || frames_.count({*producer, frame->id})) continue;
      auto cleaned = std::make_shared<agent::KeyFrame>(*frame);
      cleaned->points = runtime::withoutUavPoints(frame->points, uavs);
      add(std::move(cleaned), *producer);
    }

  std::vector<agent::OutgoingMessage> out;
  for (const auto& message : view.messages) {
    if (message.topic == kFrameTopic) {
      auto frame = decodeKeyFrame(message.bytes, fleet_);
      if (!frame) continue;
      const uint16_t producer = *producerIndex(frame->producer);
      if (frames_.count({producer, frame->id})) continue;
      if (add(decodedFrames().intern(message.bytes, std::move(*frame)), producer)) ++relayedIn_;
    } else if (message.topic == kDigestTopic) {
      const auto theirs = decodeDigest(message.bytes, fleet_.size());
      const bool inSight = std::any_of(view.neighbours.begin(), view.neighbours.end(),
                                       [&](const auto& n) { return n.name == message.from; });
      if (!theirs || !inSight) continue;
      const auto holds = [&](uint16_t producer, uint64_t id) {
        const auto it = theirs->find(producer);
        if (it == theirs->end()) return false;
        const auto& list = it->second;
        const auto range =
            std::upper_bound(list.begin(), list.end(), id,
                             [](uint64_t value, const auto& r) { return value < r.first; });
        return range != list.begin() && std::prev(range)->second >= id;
      };
      // The newest missing frames first: they describe where the fleet works now.
      std::vector<const Frames::value_type*> missing;
      for (const auto& entry : frames_)
        if (!holds(entry.first.first, entry.first.second)) missing.push_back(&entry);
      const size_t count = std::min(missing.size(), options_.framesPerReply);
      std::partial_sort(missing.begin(), missing.begin() + static_cast<long>(count), missing.end(),
                        [](const auto* a, const auto* b) {
                          return a->second->time != b->second->time
                                     ? a->second->time > b->second->time
                                     : a->first < b->first;
                        });
      for (size_t i = 0; i < count; ++i)
        out.push_back({message.from, kFrameTopic,
                       encodeKeyFrame(*missing[i]->second, missing[i]->first.first)});
    }
  }
  if (view.time - lastDigest_ >= options_.digestPeriod && !view.neighbours.empty()) {
    lastDigest_ = view.time;
    out.push_back({"", kDigestTopic, encodeDigest(ranges())});
  }
  return out;
}

std::vector<agent::KeyFrameView> KeyFrameRelay::takeNew(size_t max) {
  std::vector<agent::KeyFrameView> out;
  while (!fresh_.empty() && out.size() < max) {
    out.push_back(std::move(fresh_.front()));
    fresh_.pop_front();
  }
  return out;
}

}  // namespace coinspect::strategies::coinspect_strategy
