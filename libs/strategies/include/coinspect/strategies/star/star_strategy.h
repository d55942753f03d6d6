// `star`: team STAR's approach at CARIC (CDC 2023), on the project's runtime.
// - Explorers map with FUEL-style frontier exploration: frontier clusters of their own map near
//   the boxes, one viewpoint per cluster on rings around it (the one seeing most of it), an ATSP
//   over the viewpoints (travel + heading change) from the robot; fly to the first, plan again.
//   Explorers split the boxes' surface between them (each prefers clusters in its own share).
// - Photographers inspect the surface their map holds (from received key frames): patches of
//   their own share of the surface, viewpoints at the q_res = 1 distance by greedy set cover,
//   clustered by proximity and visibility, an ATSP over the clusters; at the q_blur = 1 speed,
//   gimbal on the patch. Units broadcast the keys of the patches they covered ("star/inspected")
//   and drop received ones from their plans, so no surface is inspected twice.
// - When the time left only just covers the way back, every UAV returns above its start, in
//   sight of the ground station.
// Config [star]: see star_options.h and doc/config.md.
#pragma once

#include <map>
#include <memory>
#include <optional>
#include <set>
#include <vector>

#include "coinspect/agent/strategy.h"
#include "coinspect/planning/camera_limits.h"
#include "coinspect/strategies/runtime/flight.h"
#include "coinspect/strategies/runtime/inspection_tour.h"
#include "coinspect/strategies/runtime/robot_map.h"
#include "coinspect/strategies/runtime/unit_info.h"
#include "coinspect/strategies/star/star_explore.h"
#include "coinspect/strategies/star/star_inspect.h"
#include "coinspect/strategies/star/star_options.h"

namespace coinspect::strategies::star {

class StarStrategy : public agent::Strategy {
 public:
  StarStrategy(const agent::StrategyContext& context, const StarOptions& options);
  ~StarStrategy() override;

  agent::AgentCommand decide(const agent::AgentView& view) override;
  double decisionRate() const override { return 10.0; }

  // For tests and logs.
  bool exploring() const { return task_ == Task::Explore; }
  const std::set<uint64_t>& inspected() const { return inspected_; }

 private:
  enum class Task { Explore, Inspect, Home };
  void initialise(const agent::AgentView& view);
  void receive(const agent::AgentView& view);
  bool givenUp(const Vec3& goal) const;  // near a goal the flight gave up on
  void explore(const agent::AgentView& view);
  // False when there is nothing left to explore. `periodic`: keep the current goal while its
  // frontier cluster is still there.
  bool planExploration(const agent::AgentView& view, bool periodic);
  void inspect(const agent::AgentView& view);
  void planInspection(const agent::AgentView& view);
  Vec3 aimTarget(const agent::AgentView& view) const;

  StarOptions options_;
  runtime::UnitInfo unit_;

  bool initialised_ = false;
  std::unique_ptr<runtime::RobotMap> map_;
  std::unique_ptr<runtime::Flight> flight_;
  std::unique_ptr<SurfaceSplit> split_;  // among the units of this role
  uint32_t part_ = 0;                    // own share of the split
  double groundZ_ = 0.0;
  Vec3 home_ = Vec3::Zero();

  Task task_ = Task::Inspect;
  double lastPlan_ = -1e300;
  std::optional<Vec3> exploreAim_;  // the frontier cluster flown to
  std::optional<Vec3> exploreGoal_;
  std::vector<Vec3> unreachable_;  // exploration goals the flight gave up on

  runtime::InspectionTour<runtime::PatchStop> tour_;  // the inspection viewpoints being flown
  std::set<uint64_t> inspected_;                      // own and received covered patches
  std::map<uint64_t, uint32_t> owner_;                // share of each patch seen so far (stable)
  bool inspectedChanged_ = false;
  double lastBroadcast_ = -1e300;
};

void registerStar(agent::StrategyRegistry& registry);

}  // namespace coinspect::strategies::star
