// The stops of an inspection plan being flown, each covering some surface keys (patches or
// waypoint bins), and the bookkeeping every inspecting strategy needs around them:
// - a stop is reached when the vehicle comes within `reachedDistance` of its body position; one of
//   the next three counts, and the stops before it were passed on the way;
// - a flight that ends short of its stops (blocked or unreachable) drops them, and their keys get
//   another chance in a later plan until they have failed `attempts` times, then are given up;
//   keys a plan found no viewpoint for fail the same way.
// `Stop` needs a `Vec3 body` member (PatchStop below, or a strategy's own).
#pragma once

#include <algorithm>
#include <cstdint>
#include <map>
#include <vector>

#include "coinspect/agent/commands.h"

namespace coinspect::strategies::runtime {

using agent::Vec3;

// The usual stop: a viewpoint covering surface patches.
struct PatchStop {
  Vec3 body = Vec3::Zero();       // where the body holds
  Vec3 target = Vec3::Zero();     // the surface point the camera looks at
  double yaw = 0.0;               // body heading there
  std::vector<uint64_t> patches;  // keys of the patches it covers
};
inline const std::vector<uint64_t>& patchKeys(const PatchStop& stop) {
  return stop.patches;
}

template <typename Stop>
class InspectionTour {
 public:
  InspectionTour(double reachedDistance, int attempts)
      : reachedDistance_(reachedDistance), attempts_(attempts) {}

  std::vector<Stop>& stops() { return stops_; }
  const std::vector<Stop>& stops() const { return stops_; }

  // The stops done by a vehicle at `position`, in tour order (none when it reached none of the
  // next three); they leave the tour.
  std::vector<Stop> takeReached(const Vec3& position) {
    const size_t ahead = std::min<size_t>(3, stops_.size());
    for (size_t i = 0; i < ahead; ++i) {
      if ((position - stops_[i].body).norm() >= reachedDistance_) continue;
      const auto end = stops_.begin() + static_cast<long>(i) + 1;
      std::vector<Stop> done(stops_.begin(), end);
      stops_.erase(stops_.begin(), end);
      return done;
    }
    return {};
  }

  // The flight ended short of the remaining stops: they leave the tour and each of their keys
  // (`keysOf(stop)`, a range of uint64_t) counts one failed attempt. Returns the keys that have
  // now failed `attempts` times, to be given up.
  template <typename KeysOf>
  std::vector<uint64_t> abandon(KeysOf keysOf) {
    std::vector<uint64_t> keys;
    for (const auto& stop : stops_)
      for (const uint64_t key : keysOf(stop))
        keys.push_back(key);
    stops_.clear();
    return fail(keys);
  }

  // A plan found no viewpoint for these keys: one failed attempt each, as above.
  std::vector<uint64_t> fail(const std::vector<uint64_t>& keys) {
    std::vector<uint64_t> givenUp;
    for (const uint64_t key : keys)
      if (++failures_[key] >= attempts_) givenUp.push_back(key);
    return givenUp;
  }

 private:
  double reachedDistance_;
  int attempts_;
  std::vector<Stop> stops_;
  std::map<uint64_t, int> failures_;  // per key: plans whose flight ended short of it
};

}  // namespace coinspect::strategies::runtime
