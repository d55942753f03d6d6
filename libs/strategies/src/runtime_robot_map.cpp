#include "coinspect/strategies/runtime/robot_map.h"

#include <algorithm>
#include <cmath>

#include "coinspect/core/error.h"
#include "coinspect/planning/coverage.h"
#include "coinspect/strategies/runtime/scan_cells_cache.h"

namespace coinspect::strategies::runtime {

namespace {
constexpr double kUavRadius = 1.5;  // m around a UAV's centre in which scan points are its own
}  // namespace

const char* toString(UnknownSpace policy) {
  switch (policy) {
    case UnknownSpace::Blocked:
      return "blocked";
    case UnknownSpace::Free:
      return "free";
    case UnknownSpace::BlockedNearBoxes:
      return "near-boxes";
  }
  return "?";
}

bool parseUnknownSpace(const std::string& text, UnknownSpace* out) {
  for (const auto policy :
       {UnknownSpace::Blocked, UnknownSpace::Free, UnknownSpace::BlockedNearBoxes}) {
    if (text == toString(policy)) {
      *out = policy;
      return true;
    }
  }
  return false;
}

namespace {

constexpr double kGroundBand = 1.0;  // m above the ground where rays never clear (raysClear...)

// raysClearAwayFromBoxes' rule, with the grid's geometry and a share of its zone (the map moves
// with its owner, so no reference to the RobotMap): rays clear outside the zone where unknown
// blocks and above the ground band.
struct RaysClearAway {
  mapping::GridFrame frame;
  std::shared_ptr<const std::vector<uint8_t>> zone;  // per grid cell
  double floor;
  bool operator()(const Vec3& p) const {
    const mapping::Index3 cell = frame.cellOf(p);
    return p.z() > floor && frame.contains(cell) && !(*zone)[frame.linear(cell)];
  }
};

// The mission region, grown to hold every point of `options.include` with the margin's room.
Aabb regionAround(const std::vector<BoxView>& boxes, const RobotMapOptions& options,
                  double groundZ) {
  Aabb region = missionRegion(boxes, options.regionMargin, groundZ);
  const Vec3 room(2.0, 2.0, 0.0);
  for (const Vec3& p : options.include) {
    region.min = region.min.cwiseMin(p - room);
    region.max = region.max.cwiseMax(p + room);
  }
  return region;
}

}  // namespace

RobotMap::RobotMap(const RobotMapOptions& options, const std::vector<BoxView>& boxes,
                   double groundZ)
    : options_(options),
      region_(regionAround(boxes, options, groundZ)),
      map_(mapping::OccupancyMapOptions{options.mapResolution, options.maxRange,
                                        options.raysClearOccupied}) {
  COINSPECT_ASSERT(options.gridResolution > 0.0 && options.rebuildPeriod >= 0.0);
  const double res = options.gridResolution;
  const mapping::Index3 size =
      ((region_.max - region_.min) / res).array().ceil().cast<int>().max(1).matrix();
  grid_ = mapping::VoxelGrid(region_.min, res, size);
  // The blocking zone is constant: computed once per cell centre.
  blockUnknown_ = std::make_shared<std::vector<uint8_t>>(
      grid_.cellCount(), options.unknown == UnknownSpace::Blocked ? 1 : 0);
  if (options.unknown == UnknownSpace::BlockedNearBoxes) {
    std::vector<BoxView> columns;
    for (const auto& box : boxes)
      columns.push_back(
          extendToGround(box, std::max(groundZ, boxBounds(box).min.z() - options.columnDepth)));
    // Per column, only the cells of its bounds grown by the margin: a cell farther from the
    // bounds is farther from the box (a scan of every cell against every box took most of the
    // start-up of a 48-robot mission).
    const Vec3 reach = Vec3::Constant(options.boxMargin + res);
    for (const auto& column : columns) {
      const Aabb bounds = boxBounds(column);
      const mapping::Index3 low = grid_.cellOf(bounds.min - reach).cwiseMax(0);
      const mapping::Index3 high =
          grid_.cellOf(bounds.max + reach).cwiseMin(size - mapping::Index3::Ones());
      for (int z = low.z(); z <= high.z(); ++z)
        for (int y = low.y(); y <= high.y(); ++y)
          for (int x = low.x(); x <= high.x(); ++x) {
            const mapping::Index3 cell(x, y, z);
            uint8_t& blocks = (*blockUnknown_)[grid_.linear(cell)];
            if (!blocks && distanceToBox(column, grid_.centre(cell)) <= options.boxMargin)
              blocks = 1;
          }
    }
    if (options.raysClearAwayFromBoxes)
      map_.setRaysClearAt(RaysClearAway{grid_.frame(), blockUnknown_, groundZ + kGroundBand});
  }
  rebuild();
}

std::vector<Vec3> uavPositions(const agent::AgentView& view) {
  std::vector<Vec3> uavs = {view.odometry.position};
  for (const auto& neighbour : view.neighbours)
    uavs.push_back(neighbour.odometry.position);
  return uavs;
}

std::vector<Eigen::Vector3f> withoutUavPoints(const std::vector<Eigen::Vector3f>& points,
                                              const std::vector<Vec3>& uavs) {
  std::vector<Eigen::Vector3f> kept;
  kept.reserve(points.size());
  for (const auto& point : points) {
    const Vec3 p = point.cast<double>();
    if (std::none_of(uavs.begin(), uavs.end(),
                     [&](const Vec3& uav) { return (p - uav).norm() < kUavRadius; }))
      kept.push_back(point);
  }
  return kept;
}

void RobotMap::insertFrame(const agent::KeyFrameView& frame) {
  if (!frame || frame->points.empty()) return;
  map_.insertScanCells(*ScanCellsCache::shared().cellsOf(frame, map_));
  ++scansInserted_;
}

void RobotMap::update(const agent::AgentView& view) {
  const std::vector<Vec3> uavs = uavPositions(view);
  const auto insert = [&](const agent::KeyFrameView& frame) {
    if (!frame || frame->points.empty()) return;
    map_.insertScan(frame->position, withoutUavPoints(frame->points, uavs));
    ++scansInserted_;
  };
  // Where the robot is, there is no obstacle: the cells its body overlaps are observed free,
  // which also clears the take-off column and any phantom left by a scan.
  std::vector<Vec3> body;
  const double reach = options_.selfClearRadius;
  const double step = options_.mapResolution;
  for (double dz = -reach; dz <= reach + 1e-9; dz += step)
    for (double dy = -reach; dy <= reach + 1e-9; dy += step)
      for (double dx = -reach; dx <= reach + 1e-9; dx += step) {
        const Vec3 p = view.odometry.position + Vec3(dx, dy, dz);
        if (Vec3(dx, dy, dz).norm() <= reach + 1e-9 && map_.state(p) != mapping::CellState::Free)
          body.push_back(p);
      }
  if (!body.empty() && view.alive) map_.observeCells(body, {});
  const bool sweeps = options_.ownSweepEvery > 0;
  if (sweeps && view.lidar.points && view.lidar.time != lastSweepTime_) {
    lastSweepTime_ = view.lidar.time;
    if (sweepCounter_++ % static_cast<size_t>(options_.ownSweepEvery) == 0 &&
        !view.lidar.points->empty()) {
      map_.insertScan(view.lidar.sensorPosition, withoutUavPoints(*view.lidar.points, uavs));
      ++scansInserted_;
    }
  }
  if (!options_.keyFramesFromView) return;
  if (!sweeps)
    for (const auto& frame : view.ownKeyFrames)
      insert(frame);
  for (const auto& frame : view.receivedKeyFrames)
    insert(frame);
}

void RobotMap::openColumn(const Vec3& bottom, double height, double radius) {
  const double res = grid_.resolution();
  const mapping::Index3 low = grid_.cellOf(bottom - Vec3(radius, radius, 0));
  const mapping::Index3 high = grid_.cellOf(bottom + Vec3(radius, radius, height));
  for (int z = std::max(0, low.z()); z <= std::min(grid_.size().z() - 1, high.z()); ++z)
    for (int y = std::max(0, low.y()); y <= std::min(grid_.size().y() - 1, high.y()); ++y)
      for (int x = std::max(0, low.x()); x <= std::min(grid_.size().x() - 1, high.x()); ++x) {
        const mapping::Index3 cell(x, y, z);
        if ((grid_.centre(cell) - bottom).head<2>().norm() <= radius + 0.5 * res)
          (*blockUnknown_)[grid_.linear(cell)] = 0;
      }
  builtRevision_ = ~uint64_t{0};  // rebuild at the next refresh, every cell
  readAll_ = true;
}

bool RobotMap::refresh(double time, bool force) {
  if (!force && (map_.revision() == builtRevision_ || time - lastRebuild_ < options_.rebuildPeriod))
    return false;
  lastRebuild_ = time;
  rebuild();
  return true;
}

void RobotMap::rebuild() {
  builtRevision_ = map_.revision();
  const auto changed = map_.takeChangedCentres();
  // The cells read again from the map: every cell at the first build and after openColumn (the
  // blocking zone changed), else those holding a map cell whose state changed, plus one cell of
  // margin against rounding (the others would read what they read last time). Copying the whole
  // map into the grid at every rebuild was most of a rebuild's cost, page faults included.
  const mapping::Index3 size = grid_.size();
  mapping::Index3 from = mapping::Index3::Zero(), to = size - mapping::Index3::Ones();
  if (!readAll_) {
    if (changed) {
      from = (grid_.cellOf(changed->first) - mapping::Index3::Ones()).cwiseMax(from);
      to = (grid_.cellOf(changed->second) + mapping::Index3::Ones()).cwiseMin(to);
    } else {
      to = from - mapping::Index3::Ones();  // nothing
    }
  }
  readAll_ = false;
  // The clearance field is then brought up to date around the cells whose blocking changed
  // only: a scan changes a few metres around the robot, and a transform of the whole grid every
  // rebuild was most of a mission's computing.
  mapping::Index3 low = size, high = mapping::Index3::Constant(-1);
  if ((from.array() <= to.array()).all()) {
    const mapping::VoxelGrid snapshot = map_.toVoxelGrid(grid_.frame(), from, to);
    const std::vector<uint8_t>& blockUnknown = *blockUnknown_;
    for (int z = from.z(); z <= to.z(); ++z)
      for (int y = from.y(); y <= to.y(); ++y) {
        size_t index = grid_.linear(mapping::Index3(from.x(), y, z));
        size_t snapshotIndex = snapshot.linear(mapping::Index3(0, y - from.y(), z - from.z()));
        for (int x = from.x(); x <= to.x(); ++x, ++index, ++snapshotIndex) {
          mapping::CellState state = snapshot.stateAt(snapshotIndex);
          if (state == mapping::CellState::Unknown && !blockUnknown[index])
            state = mapping::CellState::Free;
          const mapping::CellState before = grid_.stateAt(index);
          if (state == before) continue;
          grid_.setAt(index, state);
          if (grid_.blocksClearance(state) == grid_.blocksClearance(before)) continue;
          const mapping::Index3 cell(x, y, z);
          low = low.cwiseMin(cell);
          high = high.cwiseMax(cell);
        }
      }
  }
  if (grid_.hasClearance())
    grid_.updateClearance(low, high);
  else
    grid_.computeClearance(options_.clearanceCap, true);
  ++gridVersion_;
}

std::vector<mapping::SurfaceVoxel> RobotMap::surfaceNearBoxes(const std::vector<BoxView>& boxes,
                                                              double nearBox) const {
  std::vector<mapping::SurfaceVoxel> out;
  const double cell = map_.options().resolution;
  for (const auto& voxel : map_.surfaceVoxels(region_.min, region_.max)) {
    if (planning::isGroundSurface(voxel, region_.min.z(), cell)) continue;
    for (const auto& box : boxes)
      if (distanceToBox(box, voxel.centre) <= nearBox) {
        out.push_back(voxel);
        break;
      }
  }
  return out;
}

}  // namespace coinspect::strategies::runtime
