// `coinspect`: our CARIC strategy. Lessons of the competition, as design rules:
// - Explore and inspect at the same time: explorers first fly standoff orbits around the boxes
//   (their LiDAR maps the structure and their key frames reach whoever is in sight), then join
//   the inspection; photographers inspect whatever surface their map already holds.
// - Split the work by surface, not by box volume, and without talking: every robot runs the same
//   deterministic partition of the boxes' faces (common knowledge) in proportion to capacities
//   (explorers, busy mapping first, get less), then inspects the mapped surface of its region.
// - Inspect at full quality: viewpoints at the distance where q_res ~ 1, chosen by greedy set
//   cover of the mapped surface patches, visited in a short open tour at a speed that keeps
//   q_blur = 1, with the body facing the surface and the gimbal on it.
// - Share the map: every robot (the ground station too) keeps the key frames it got and
//   relays them to neighbours that lack them (keyframe_relay.h), so a photographer maps what an
//   explorer saw out of its sight.
// - Rebalance: robots report the patches they viewed (shared_progress.h); one whose region is
//   finished helps with the rest of the fleet's work, which also covers a robot that failed.
// - Deliver: the score counts only once the ground station merged a robot's log, so robots go
//   back into its line of sight periodically and before the end.
//
// Config ([coinspect], every key optional):
//   explore_time = 300        s, explorers map for at most this long before inspecting
//   explore_standoff = 12     m from the boxes' bounds for the exploration orbits
//   view_distance = 0.9       fraction of the full-resolution distance to hold the camera at
//   replan_period = 8         s between inspection plans
//   transit_speed = 4         m/s between inspection stretches
//   explorer_capacity = 0.6   share of an explorer in the work partition (photographer = 1)
//   deliver_period = 150      s without ground-station contact before taking captures home
#pragma once

#include <map>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "coinspect/agent/strategy.h"
#include "coinspect/planning/camera_limits.h"
#include "coinspect/planning/coverage.h"
#include "coinspect/strategies/coinspect/gcs_contact.h"
#include "coinspect/strategies/coinspect/keyframe_relay.h"
#include "coinspect/strategies/coinspect/shared_progress.h"
#include "coinspect/strategies/coinspect/work_partition.h"
#include "coinspect/strategies/runtime/flight.h"
#include "coinspect/strategies/runtime/inspection_tour.h"
#include "coinspect/strategies/runtime/robot_map.h"
#include "coinspect/strategies/runtime/unit_info.h"

namespace coinspect::strategies::coinspect_strategy {

struct CoinspectOptions {
  double exploreTime = 300.0;
  double exploreStandoff = 12.0;
  double viewDistance = 0.9;
  double replanPeriod = 8.0;
  double transitSpeed = 4.0;
  double explorerCapacity = 0.6;
  DeliveryOptions delivery;

  // Reads [coinspect]; throws InputError naming the file and key for bad values.
  static CoinspectOptions read(const Config& config);
};

class CoinspectStrategy : public agent::Strategy {
 public:
  CoinspectStrategy(const agent::StrategyContext& context, const CoinspectOptions& options);
  ~CoinspectStrategy() override;

  agent::AgentCommand decide(const agent::AgentView& view) override;
  double decisionRate() const override { return 10.0; }

 private:
  enum class Task { Explore, Inspect, Deliver };
  void initialise(const agent::AgentView& view);
  std::vector<Vec3> explorationRoute(const agent::AgentView& view) const;
  void planInspection(const agent::AgentView& view);
  agent::AgentCommand command(const agent::AgentView& view, agent::AgentSetpoint setpoint);

  CoinspectOptions options_;
  runtime::UnitInfo unit_;

  bool initialised_ = false;
  std::unique_ptr<runtime::RobotMap> map_;
  std::unique_ptr<runtime::Flight> flight_;
  std::vector<WorkItem> work_;
  std::vector<uint32_t> workRegion_;
  uint32_t region_ = 0;
  GcsContact contact_;
  KeyFrameRelay relay_;
  SharedProgress progress_;

  Task task_ = Task::Inspect;
  Task resume_ = Task::Inspect;  // what to go back to after a delivery
  double lastPlan_ = -1e300;
  runtime::InspectionTour<runtime::PatchStop> tour_;  // the viewpoints being flown
  std::set<uint64_t> inspected_;        // patch keys viewed (or given up after kAttemptsPerPatch)
  std::map<uint64_t, uint32_t> owner_;  // region of each patch seen so far (stable)
};

void registerCoinspect(agent::StrategyRegistry& registry);

}  // namespace coinspect::strategies::coinspect_strategy
