// SLEI3D's ground-station layer as pure functions every robot can evaluate the same way: the
// fleet split into subgroups (one explorer each), the rolling choice of boxes, and the places
// where a subgroup meets the station (doc/strategies.md, "SLEI3D").
#pragma once

#include <cstdint>
#include <vector>

#include "coinspect/agent/observations.h"
#include "coinspect/planning/ground_path.h"
#include "coinspect/strategies/slei/protocol.h"

namespace coinspect::strategies::slei {

// How many inspectors each of `explorers` subgroups gets: evenly (the reference code: the first
// `inspectors % explorers` get one more), or in proportion to `weights` (the paper: the volume of
// each subgroup's first box; floor of the share, the remainder one each to the largest
// fractional parts, ties to the earlier subgroup).
std::vector<size_t> inspectorsPerSubgroup(size_t inspectors, size_t explorers, bool even,
                                          const std::vector<double>& weights = {});

// The unassigned box (assigned[i] == 0) whose footprint centre is nearest, horizontally, to
// `from`, among the high-priority boxes while one is unassigned; -1 when none is left. Ties go
// to the lower index.
int32_t nearestFreeBox(const std::vector<agent::BoxView>& boxes,
                       const std::vector<uint8_t>& assigned, const Vec3& from);

// The fully unknown workspace (the paper's extension; `[slei3d] workspace = unknown`): the
// robots know the bounds of the whole area, not where its structures stand.
// The world-aligned bounds of every box (rotated boxes included), as one box.
agent::BoxView workspaceBox(const std::vector<agent::BoxView>& boxes);
// The paper's first split: `parts` equal slabs across the longer horizontal side, in order along
// it (none for 0 parts).
std::vector<agent::BoxView> splitWorkspace(const agent::BoxView& workspace, size_t parts);
// One step of the paper's octree partition: the box halved along every edge longer than
// `maxEdge` (2, 4 or 8 parts, x fastest, then y, then z); none when no edge is longer. The parts
// keep the box's priority. Without `splitHeight` only the footprint is halved: each part keeps
// the box's full height (and its roof, for a roof pass over it).
std::vector<agent::BoxView> octreeChildren(const agent::BoxView& box, double maxEdge,
                                           bool splitHeight = true);

// SLEI-PRE's fixed box orders (the paper's baseline without rolling assignment): given each
// subgroup's first box (-1: none), the other boxes are dealt in turns, each subgroup taking the
// free box nearest its last one (nearestFreeBox), until none is left. Returns, per subgroup,
// the boxes after its first, in the order it will explore them. `taken` (per box, or empty)
// marks boxes that are not to be dealt (another station's).
std::vector<std::vector<int32_t>> fixedBoxOrders(const std::vector<agent::BoxView>& boxes,
                                                 const std::vector<int32_t>& firstBoxes,
                                                 const std::vector<uint8_t>& taken = {});

// Failure recovery with fixed orders: the box of the lost subgroup `lost` goes to the end of the
// shortest list of the others (ties to the lower index); nothing when there is no other.
void giveBoxToShortestOrder(std::vector<std::vector<int32_t>>& orders, size_t lost, int32_t box);

// Of the four corners of the box's world-aligned bounds moved `offset` m outwards in x and y,
// at height z, the one nearest (horizontally) to `from` (planning::nearestMeetingCorner). The
// reference uses corners 1 m inside the box (its robots' maps extend 2 m beyond it); the boxes
// here hug their structure, so the corners are outside, where the ground station can stand and
// a UAV can fly before anything is mapped.
Vec3 boxCorner(const agent::BoxView& box, double offset, double z, const Vec3& from);
// The same for boxes[index], skipping corners that fall inside another box's footprint (slei-b's
// four boxes share one building: a corner between two of them is inside it, where the station
// cannot drive); the nearest corner when every one does.
Vec3 boxCorner(const std::vector<agent::BoxView>& boxes, size_t index, double offset, double z,
               const Vec3& from);

// `corner` moved `distance` m horizontally away from the box's footprint centre, at height z:
// where a UAV waits near a corner without crowding the structure or the station there.
Vec3 awayFromBox(const agent::BoxView& box, const Vec3& corner, double distance, double z);

// Where inspector k of a subgroup waits off box `index`'s corner, at height z: the k-th point,
// nearest the corner first, of a square lattice `spacing` apart that starts 3 m out on the line
// from the box's centre through the corner (two columns either side of it) and leaves out points
// within 1.5 m of any box's footprint (another structure: unknown space, and no way there). The
// spacing must exceed the flight's hold distance to a higher-priority neighbour
// (runtime::FlightOptions::separation): one waiting at its point otherwise holds the next away
// from its own for good.
Vec3 waitPointOffCorner(const std::vector<agent::BoxView>& boxes, size_t index, const Vec3& corner,
                        size_t k, double spacing, double z);

// caric-team: where the index-th of `count` inspectors waits around the relay, on circles about
// it at its height: the first of radius `radius`, each next one `ringGap` further out, as many
// on a circle as it holds with neighbours at least `minChord` apart (the flight's hold distance:
// 4 on the first when `radius` is 3 m, 4.24 m apart), spread evenly.
Vec3 relayWaitPoint(const Vec3& relay, size_t index, size_t count, double radius, double minChord,
                    double ringGap);

// Which of the station's meetings (their times, in the order it plans to serve them) it drives
// to now: the first, unless the first is not due yet and another one is overdue (its time has
// passed), then the earliest overdue one. The order with time windows puts a window it can no
// longer meet after those it can, and the station waited at the next stop for its time while
// the late explorer waited at its own place (slei-a, scene seed 1, explorer1 lost at 338 s:
// explorer2 waited from 358 s to the end). Empty: 0.
size_t meetingToServe(const std::vector<double>& times, double now);

inline constexpr double kGroundClearance = 0.5;  // m a station keeps beyond its radius

// The ground a station of collision radius `radius` knows from the start: a grid over the boxes
// and `also` with 15 m around, the boxes' footprints blocked (inflated by the radius and
// kGroundClearance).
// `blockFootprints` false (the unknown workspace: its boxes are parts of the area, not
// structures): only the grid's extent comes from the boxes.
planning::GroundGrid stationGroundGrid(const std::vector<agent::BoxView>& boxes,
                                       const planning::Vec2& also, double radius,
                                       bool blockFootprints = true);

// What the station learns of its ground from the LiDAR points it carries (key frames relayed
// by the explorers, world frame): a point between 0.3 and 2 m above `groundZ` is an obstacle
// for a ground vehicle (a wall outside every box; the ground itself and overhangs are not),
// blocked with `inflate` m around it (once per ground cell). Returns the cells newly blocked.
size_t blockGroundObstacles(planning::GroundGrid& ground,
                            const std::vector<Eigen::Vector3f>& points, double groundZ,
                            double inflate);

// What one ground station runs (the paper's several GCS: each with its explorers, in
// parallel), the same for every robot since it depends on the fleet and the boxes only: the
// explorers in contiguous blocks in fleet order, as even as they go (the first stations get one
// more); the inspectors likewise, in proportion to the explorers; the boxes in strips along the
// longer horizontal spread of their centres, ascending (the generated fleets stand their
// stations in a row along x in fleet order), each station's strip of a volume in proportion to
// its explorers: a box goes to the station in whose share the middle of its volume falls. One
// station gets everything. In the order of the stations in the fleet.
struct StationShare {
  uint32_t station = 0;  // fleet index
  std::vector<uint32_t> explorers, inspectors;
  std::vector<double> explorerRanges;  // per explorer: its detector range (FleetMember)
  std::vector<uint8_t> boxes;          // per box: 1 when it is this station's
};
std::vector<StationShare> stationShares(const std::vector<agent::FleetMember>& fleet,
                                        const std::vector<agent::BoxView>& boxes);

struct PlanOptions {
  bool evenSplit = true;
  double cornerOffset = 2.0;       // m outside the box's bounds (boxCorner)
  double stationSpeed = 1.0;       // m/s
  double firstMeetingLead = 60.0;  // s before the first meetings (the reference: 60)
  double legBuffer = 20.0;  // s added per leg of the station's first round (the reference: 20)
};

// A station's first plan for its share, made at `now` from where it stands: its explorers in
// fleet order each take the free box of its share nearest the previous choice (the first:
// nearest the station), its inspectors are split in fleet order; each subgroup's first meeting
// is at the corner of its box nearest the previous meeting (the station's own position first),
// at times chained as the station would drive them (straight legs at stationSpeed + legBuffer,
// after firstMeetingLead). Explorers of different detector ranges (the paper's heterogeneous
// explorers): the first boxes so chosen are dealt again, the largest to the longest range (ties
// in fleet order).
FleetPlan makeFleetPlan(const StationShare& share, const std::vector<agent::BoxView>& boxes,
                        const Vec3& station, double groundZ, double now,
                        const PlanOptions& options);

}  // namespace coinspect::strategies::slei
