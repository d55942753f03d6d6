// `kios`: the approach of team KIOS CoE / CyCLOPS, winner of CARIC at CDC 2023.
// - The operational volume (the boxes' bounds) is a voxel graph: the RobotMap's planning grid.
// - Explorers split the volume into slabs along its longest horizontal axis (one each, fleet
//   order) and sweep their slab in lawnmower passes along that axis at a few heights and above
//   the top (kios/sweep.h); their LiDAR key frames map the structure for whoever is in sight.
// - Photographers derive inspection waypoints from their own map: free cells next to occupied
//   ones with a view direction, seen from the q_res = 1 distance (kios/waypoints.h). Every
//   `replan_period` s (receding horizon) each photographer solves the same min-max mTSP over the
//   photographers seen at take-off (started at the centres of their shares of the volume, which
//   every unit knows) and the waypoints not visited yet, and flies the first stops of its share
//   (ordered from where it is) at the blur-free speed, body and gimbal on the waypoint's surface
//   point. Visited waypoints are remembered and broadcast (topic "kios/visited") to neighbours in
//   sight.
// - Explorers fly their sweep a stretch at a time and start a new one (at shifted heights) when
//   it ends.
// - When the time left only just covers the way back, every UAV returns above its start, in
//   line of sight of the ground station, so its captures are merged.
//
// Config [kios] (every key optional; doc/config.md):
//   explore_standoff = 10     m outside the volume's long sides for the explorers' passes
//   explore_heights = 2       side passes per explorer, evenly spread in height
//   lane_spacing = 40         m at most between the passes above the top
//   view_distance = 0.9       fraction of the q_res = 1 distance to hold the camera at
//   waypoint_spacing = 0      m between waypoints (bin size); 0: 0.6 x the vertical footprint
//   replan_period = 6         s between mTSP plans
//   stops_per_plan = 10       stops of the own route flown before the next plan
//   max_waypoints = 150       waypoints per plan (those nearest a vehicle start)
//   max_speed = 4             m/s (photographers inspect at most at the blur-free speed)
//   safety_margin = 0.8       m kept between a UAV's sphere and any mapped surface
//   map_resolution = 1        m, cell of the robot's map (planning grid: 1 m)
//   mtsp_seed = 1             seed of the mTSP search, the same in every robot
//   broadcast_visited = true  send visited waypoint ids to neighbours
//   return_home = true        return above the start for the last seconds
//   mtsp_starts = shares      shares: the mTSP starts every photographer at the centre of its
//                             share of the volume (the same in every robot), then orders its own
//                             waypoints by a TSP from where it is; positions: from where each
//                             photographer is (own) or was last seen (others)
#pragma once

#include <cstdint>
#include <map>
#include <memory>
#include <set>
#include <string>
#include <vector>

#include "coinspect/agent/strategy.h"
#include "coinspect/planning/camera_limits.h"
#include "coinspect/strategies/kios/waypoints.h"
#include "coinspect/strategies/runtime/flight.h"
#include "coinspect/strategies/runtime/inspection_tour.h"
#include "coinspect/strategies/runtime/robot_map.h"
#include "coinspect/strategies/runtime/unit_info.h"

namespace coinspect::strategies::kios {

inline constexpr const char* kVisitedTopic = "kios/visited";

struct KiosOptions {
  double exploreStandoff = 10.0;
  int exploreHeights = 2;
  double laneSpacing = 40.0;
  double viewDistance = 0.9;
  double waypointSpacing = 0.0;
  double replanPeriod = 6.0;
  int stopsPerPlan = 10;
  int maxWaypoints = 150;
  double maxSpeed = 4.0;
  double safetyMargin = 0.8;
  // 0.5 m: at 1 m a wing's rear half shared its cells with the free space above it, rays over
  // the wing marked them free and a photographer flew into the trailing edge (generated hangar,
  // seed 2); 0.5 m also scored higher (CARIC MBS seed 1: 796 -> 967) at twice the compute.
  double mapResolution = 0.5;
  uint64_t mtspSeed = 1;
  bool broadcastVisited = true;
  bool returnHome = true;
  bool anchoredStarts = true;

  // Reads [kios]; throws InputError naming the file and key for a bad value.
  static KiosOptions read(const Config& config);
};

// Visited ids as message bytes (8 bytes each, little endian) and back; a truncated tail is
// ignored.
std::vector<uint8_t> encodeIds(const std::vector<uint64_t>& ids);
std::vector<uint64_t> decodeIds(const std::vector<uint8_t>& bytes);

class KiosStrategy : public agent::Strategy {
 public:
  KiosStrategy(const agent::StrategyContext& context, const KiosOptions& options);
  ~KiosStrategy() override;

  agent::AgentCommand decide(const agent::AgentView& view) override;
  double decisionRate() const override { return 10.0; }

 private:
  void initialise(const agent::AgentView& view);
  void startSweep(const agent::AgentView& view);
  void followSweep();
  void plan(const agent::AgentView& view);
  void stage(const agent::AgentView& view);
  // Centre of photographer `rank`'s share of the volume: its part of the long axis, mid-height.
  Vec3 shareCentre(size_t rank) const;
  void followStops();
  double viewingDistance() const;
  double inspectSpeed() const;

  KiosOptions options_;
  runtime::UnitInfo unit_;

  bool initialised_ = false;
  std::unique_ptr<runtime::RobotMap> map_;
  std::unique_ptr<runtime::Flight> flight_;
  runtime::Aabb volume_;  // the boxes' bounds, from the ground up
  double groundZ_ = 0.0;
  Vec3 home_ = Vec3::Zero();
  bool goingHome_ = false;
  int sweeps_ = 0;
  std::vector<Vec3> sweep_;  // the explorer's current sweep
  size_t sweepNext_ = 0;     // first waypoint of it not handed to Flight yet

  // Photographers known at take-off (fleet order) and where each was last seen.
  std::vector<std::string> photographers_;
  std::map<std::string, Vec3> lastSeen_;
  double lastPlan_ = -1e300;
  runtime::InspectionTour<InspectionWaypoint> tour_;  // the own waypoints being flown
  bool transit_ = false;  // flying to the first stop at max_speed (no capture expected on the way)
  std::set<uint64_t> visited_;
};

void registerKios(agent::StrategyRegistry& registry);

}  // namespace coinspect::strategies::kios
