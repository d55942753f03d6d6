// One robot's map as strategies use it: an OccupancyMap fed from the AgentView, and a dense
// planning grid (with clearance) over the mission region, rebuilt only when the map changed and
// at most every `rebuildPeriod` s, because a rebuild costs a snapshot plus a distance transform.
//
// Unknown space: `Blocked` keeps every unknown cell closed; `Free` opens all of them (a robot
// that trusts the boxes alone); `BlockedNearBoxes` closes unknown cells only within `boxMargin`
// of a box extended `columnDepth` m downwards (towers stand on the ground below their boxes),
// where unseen structure can be, and opens the rest. Occupied cells always block.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "coinspect/agent/agent_view.h"
#include "coinspect/mapping/occupancy_map.h"
#include "coinspect/mapping/voxel_grid.h"
#include "coinspect/strategies/runtime/box_geometry.h"

namespace coinspect::strategies::runtime {

enum class UnknownSpace { Blocked, Free, BlockedNearBoxes };
// "blocked", "free", "near-boxes"; parseUnknownSpace returns false for any other text.
const char* toString(UnknownSpace policy);
bool parseUnknownSpace(const std::string& text, UnknownSpace* out);

struct RobotMapOptions {
  double mapResolution = 0.5;   // m, map cell
  double maxRange = 30.0;       // m, LiDAR returns farther away only clear free space
  double gridResolution = 1.0;  // m, planning grid cell
  double regionMargin = 12.0;   // m around the boxes' bounds (orbits must fit inside)
  double rebuildPeriod = 2.0;   // s, minimum time between grid rebuilds
  double clearanceCap = 6.0;    // m, distance field cap (> any required clearance)
  UnknownSpace unknown = UnknownSpace::BlockedNearBoxes;
  double boxMargin = 2.0;     // m, BlockedNearBoxes: unknown blocks this close to a box
  double columnDepth = 10.0;  // m below a box (not below the ground) that counts as near it
  // Explorers: insert every n-th own LiDAR sweep (0: own key frames only, as receivers do).
  int ownSweepEvery = 0;
  // m: cells within this distance of the robot are observed free at every update (a robot's
  // body occupies them, so nothing else can); 0 disables it.
  double selfClearRadius = 1.0;
  // update() inserts the view's own and received key frames; false when the strategy hands
  // them over itself (insertFrame), e.g. after relaying them between robots.
  bool keyFramesFromView = true;
  // false: LiDAR rays passing through an occupied cell leave it occupied (the scenes are
  // static; see mapping::OccupancyMapOptions): a thin wing's trailing edge, seen at grazing
  // angles, was erased and a photographer flew into it. Only a robot's body clears such a cell.
  bool raysClearOccupied = false;
  // BlockedNearBoxes only: rays do clear occupied cells outside the blocking zone and more than
  // 1 m above the ground (structure stands in the boxes; a UAV seen there from afar, beyond the
  // link that would have told where it was, is gone once rays pass through).
  bool raysClearAwayFromBoxes = false;
  // Points the region must also hold (2 m around them horizontally), e.g. where the robot
  // starts: a start outside the boxes' region plus margin could not plan its way in.
  std::vector<Vec3> include;
};

// The UAVs a robot knows to be near now: itself and its neighbours in line of sight.
std::vector<Vec3> uavPositions(const agent::AgentView& view);
// `points` without those within 1.5 m of a UAV (LiDAR returns of rotors and bodies: moving
// robots would otherwise leave phantom obstacles in the map).
std::vector<Eigen::Vector3f> withoutUavPoints(const std::vector<Eigen::Vector3f>& points,
                                              const std::vector<Vec3>& uavs);

class RobotMap {
 public:
  // `groundZ`: the height robots start from (the region's floor).
  RobotMap(const RobotMapOptions& options, const std::vector<BoxView>& boxes, double groundZ);
  // One per robot: a copy would share its zone of blocked unknown space with the original.
  RobotMap(const RobotMap&) = delete;
  RobotMap& operator=(const RobotMap&) = delete;
  RobotMap(RobotMap&&) = default;
  RobotMap& operator=(RobotMap&&) = default;

  // Inserts what the view brings: own sweeps or own key frames, and received key frames.
  void update(const agent::AgentView& view);
  // Inserts a key frame as it is (its UAV points already removed); the cells it observes are
  // found once for all robots inserting the same frame object (ScanCellsCache::shared()).
  void insertFrame(const agent::KeyFrameView& frame);
  // Rebuilds the planning grid when the map changed since the last rebuild and `rebuildPeriod`
  // has passed since it (or when `force`). True when it rebuilt.
  bool refresh(double time, bool force = false);
  // Unknown cells within `radius` of the vertical segment from `bottom` up `height` m are
  // opened (from the next rebuild on): where a robot stood and climbed is known to be free.
  void openColumn(const Vec3& bottom, double height, double radius);

  const mapping::OccupancyMap& map() const { return map_; }
  // The mapped surface worth inspecting: surface voxels within `nearBox` m of a box, not the
  // ground (planning::isGroundSurface against the region's floor, where robots start).
  std::vector<mapping::SurfaceVoxel> surfaceNearBoxes(const std::vector<BoxView>& boxes,
                                                      double nearBox) const;
  // Unknown cells outside the policy's blocking zone already read Free; the clearance field
  // counts the remaining Unknown cells as obstacles.
  const mapping::VoxelGrid& grid() const { return grid_; }
  uint64_t gridVersion() const { return gridVersion_; }
  const Aabb& region() const { return region_; }
  const RobotMapOptions& options() const { return options_; }
  size_t scansInserted() const { return scansInserted_; }

 private:
  void rebuild();

  RobotMapOptions options_;
  Aabb region_;
  mapping::OccupancyMap map_;
  mapping::VoxelGrid grid_;
  // Per grid cell: unknown here stays blocked. Shared with the map's rays-clear rule
  // (raysClearAwayFromBoxes), which must not keep a copy of its own per robot.
  std::shared_ptr<std::vector<uint8_t>> blockUnknown_;
  uint64_t gridVersion_ = 0;
  uint64_t builtRevision_ = 0;
  bool readAll_ = true;  // the next rebuild reads every cell from the map, not the changed ones
  double lastRebuild_ = -1e300;
  size_t sweepCounter_ = 0;
  double lastSweepTime_ = -1.0;
  size_t scansInserted_ = 0;
};

}  // namespace coinspect::strategies::runtime
