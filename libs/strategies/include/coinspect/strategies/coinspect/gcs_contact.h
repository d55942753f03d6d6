// Delivering captures: the score only counts once the ground station has merged a robot's log,
// which needs direct line of sight. A robot remembers where it last had the station in sight
// and decides when to go back there: periodically while it has undelivered captures, and early
// enough before the end of the mission to make it.
#pragma once

#include <optional>
#include <vector>

#include "coinspect/agent/agent_view.h"

namespace coinspect::strategies::coinspect_strategy {

using agent::Vec3;

struct DeliveryOptions {
  double period = 150.0;      // s without contact after which undelivered work is taken home
  double minGain = 5.0;       // score points of undelivered work that justify the trip
  double endMargin = 25.0;    // s kept in hand when heading home for the end of the mission
  double assumedSpeed = 3.0;  // m/s, for the time needed to reach a contact point
  double spacing = 8.0;       // m between remembered contact points
};

class GcsContact {
 public:
  explicit GcsContact(const DeliveryOptions& options = {}) : options_(options) {}

  // Call at every decision: notes contacts (a ground station among the neighbours) and gains.
  void observe(const agent::AgentView& view);

  bool inContact() const { return inContact_; }
  double undeliveredGain() const { return undelivered_; }
  // Where to go to deliver: the remembered contact point nearest to `from` (none if never seen).
  std::optional<Vec3> nearestContactPoint(const Vec3& from) const;
  // True when the robot should fly to a contact point now.
  bool shouldDeliver(const agent::AgentView& view) const;

 private:
  DeliveryOptions options_;
  std::vector<Vec3> points_;
  bool inContact_ = false;
  double lastContact_ = 0.0;
  double undelivered_ = 0.0;
};

}  // namespace coinspect::strategies::coinspect_strategy
