// slei3d, an explorer: explore the box, hand features to the inspectors, meet the station.
#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

#include "coinspect/planning/detection_coverage.h"
#include "coinspect/planning/meeting_decision.h"
#include "coinspect/planning/path_search.h"
#include "coinspect/planning/slei_schedule.h"
#include "coinspect/strategies/runtime/box_geometry.h"
#include "coinspect/strategies/slei/inspector_forecast.h"
#include "coinspect/strategies/slei/slei3d_strategy.h"
#include "coinspect/strategies/star/star_explore.h"

namespace coinspect::strategies::slei {

namespace {

constexpr double kReplanPeriod = 15.0;   // s between sweep plans (the map grows meanwhile)
constexpr double kStationAntenna = 0.5;  // m above the ground, a station's link end
constexpr double kApproachReach = 4.5;   // m: within the 5 m link with a margin
constexpr double kHubSlot = 3.0;  // m from a static station where each of its explorers meets it
const Vec3 kParkAbove(0.0, 0.0, 6.0);    // a static station's explorer with nothing left: up there
constexpr double kApproachRetry = 3.0;   // s between approaches after a failed flight
constexpr double kReaimPeriod = 5.0;     // s between checks of a station meeting point ...
constexpr double kReaimOffset = 1.0;     // m ... left by more than this: flown to again
constexpr double kEarlyPatience = 30.0;  // s past the expected time at an early stop
constexpr double kLostFor = 60.0;        // s an inspector missed twice is not looked for
constexpr double kPresumedFailed = 120.0;   // s without its status: a missed inspector failed
constexpr double kMaxHandoutWait = 15.0;    // s an explorer may plan to wait for an inspector
constexpr double kSweepPassRadius = 1.0;    // m from a stop flown through: there
constexpr double kTurnTime = 1.5;           // s at a sweep stop for the heading to come round
constexpr double kSurfaceNearBox = 1.0;     // m: mapped surface this close to the box is its own
constexpr double kPatchSize = 2.0;          // m, surface patches the detector sweeps
constexpr size_t kPatchesPerPlan = 300;     // nearest open patches a plan covers
constexpr double kBoxMargin = 2.0;          // m around the box where frontiers count (FUEL's map)
constexpr double kUnreachableRadius = 2.0;  // m around a given-up goal that is skipped
constexpr double kReportPeriod = 1.0;       // s between repeats of a report or orders
constexpr double kLeaveMargin = 10.0;       // s: leave for the station this early (the reference)
constexpr double kTravelFactor = 1.5;       // paths are longer than straight lines
constexpr double kSettle = 2.0;             // s an inspector needs at a pose beyond t_q
constexpr double kInspectionTime = 3.0;     // s, t_q ([features] inspect_time's default)
constexpr double kHubReach = 10.0;          // m from caric-team's hub where it hands out
constexpr double kPoseTravel = 5.0;         // s between two poses of a list, a rough guess
// s past a station meeting an explorer with no box left may still be collecting results: half
// the station's patience (six graces of 10 s, slei3d_station.cpp).
constexpr double kCollectOverrun = 30.0;
constexpr double kNoMeeting = 1e299;
constexpr double kCharged = 0.99;         // battery level at which it stops charging
constexpr double kChargePatience = 20.0;  // s without the level rising: no charger in reach
constexpr double kChargeHeight = 0.8;     // share of the charge range above the station
constexpr double kRoofPassRise = 0.5;     // m above the lowest flyable height over a box
constexpr double kApproachAfter = 1.0;    // s past a hand-out's time before approaching
constexpr double kApproachStop = 1.5;     // m short of the inspector's predicted place
constexpr double kFetchStop = 2.0;        // s an exchange of results takes, with the approach

// The roof pass over `box` at height `z`: the corner of its footprint nearest `from`, then the
// opposite one (the flight between crosses the box; from the two corners the LiDAR looks down
// on all four sides of a stepped roof).
std::vector<Vec3> roofPassStops(const agent::BoxView& box, const Vec3& from, double z) {
  const auto footprint = runtime::footprintOf(box);
  std::vector<Vec3> corners;
  for (const double su : {-1.0, 1.0})
    for (const double sv : {-1.0, 1.0}) {
      const runtime::Vec2 c = footprint.centre + su * footprint.half[0] * footprint.axis[0] +
                              sv * footprint.half[1] * footprint.axis[1];
      corners.emplace_back(c.x(), c.y(), z);
    }
  size_t nearest = 0;
  for (size_t k = 1; k < corners.size(); ++k)
    if ((corners[k] - from).head<2>().norm() < (corners[nearest] - from).head<2>().norm())
      nearest = k;
  return {corners[nearest], corners[3 - nearest]};  // index 3 - k is the diagonal opposite
}

double straightTime(const Vec3& a, const Vec3& b, double speed) {
  return kTravelFactor * (a - b).norm() / speed;
}

}  // namespace

planning::InspectorPlan Slei3dStrategy::predictedPlan(const InspectorModel& model, double now,
                                                      bool presumeDone) const {
  InspectorForecast inspector{
      static_cast<int>(model.unit), model.position, model.since, {}, model.home};
  for (const auto& task : model.tasks)
    inspector.poses.push_back(task.viewPosition);
  // presumeDone: without it, in 11 of 20 missed hand-outs of a slei-a run the inspector was at
  // or on its way to its wait point, its list done, while the explorer's plan still had it at
  // its first listed feature (doc/strategies.md, "Hand-outs (SOEI)").
  return forecastInspector(inspector, now,
                           {options_.speed, kTravelFactor, kInspectionTime, kSettle, presumeDone});
}

void Slei3dStrategy::enterBox(const agent::AgentView& view, int32_t box) {
  box_ = box;
  boxStart_ = view.time;
  explorationFinished_ = false;
  scannedInBox_ = 0;
  inspectedInBox_ = 0;
  boxFeatures_.clear();
  sweptInBox_ = 0;
  openList_.clear();
  sweepRoute_.clear();
  atStopSince_ = -1.0;
  toFrontier_ = false;
  openPatches_ = 0;
  unreachable_.clear();
  exploreAim_.reset();
  roofPass_.clear();
  if (box >= 0 && options_.roofPass && !options_.unknownWorkspace) {
    // Above the space kept blocked over the box while unknown, with the clearance a path
    // needs (the flight would not plan into it).
    const auto& b = boxes_[static_cast<size_t>(box)];
    const double z = runtime::boxBounds(b).max.z() + options_.unknownBoxMargin +
                     flight_->requiredClearance(map_->grid()) + kRoofPassRise;
    roofPass_ = roofPassStops(b, view.odometry.position, z);
  }
  if (box < 0) {
    phase_ = ExplorerPhase::Done;
    return;
  }
  boxFrom_ = view.odometry.position;
  if (options_.unknownWorkspace) {
    // A part's corner may stand inside a structure: it explores from where it is (its frontiers
    // and surface lead it into the box).
    phase_ = ExplorerPhase::Exploring;
    lastPlan_ = -1e300;
  } else {
    phase_ = ExplorerPhase::ToBox;
    flight_->goTo(boxEntry(box, boxFrom_), options_.speed);
  }
  // Every inspector of the subgroup waits off the new corner once its list is done; it learns
  // of it at its next orders (caric-team's inspectors keep waiting at the relay).
  if (options_.variant == SleiVariant::Team) return;
  for (size_t k = 0; k < inspectors_.size(); ++k)
    inspectors_[k].waitAt = waitPointNear(box, boxFrom_, k);
}

Vec3 Slei3dStrategy::boxEntry(int32_t box, const Vec3& from) const {
  return boxCorner(boxes_, static_cast<size_t>(box), options_.plan.cornerOffset,
                   groundZ_ + options_.exploreHeight, from);
}

std::vector<planning::InspectionPatch> Slei3dStrategy::unsweptPatches(
    const agent::BoxView& box) const {
  std::vector<planning::InspectionPatch> open;
  for (const auto& patch :
       planning::groupSurface(map_->surfaceNearBoxes({box}, kSurfaceNearBox), kPatchSize))
    if (!swept_.count(patch.key)) open.push_back(patch);
  return open;
}

std::vector<agent::BoxView> Slei3dStrategy::remainderParts() const {
  if (!(options_.unknownWorkspace || options_.shareWork) || fixedRegions() || box_ < 0) return {};
  std::vector<agent::BoxView> out;
  // A known box is split across its footprint only: each part keeps its roof.
  for (const auto& part : octreeChildren(boxes_[static_cast<size_t>(box_)], options_.leafEdge,
                                         options_.unknownWorkspace)) {
    bool open = !unsweptPatches(part).empty();
    if (!open) {
      const auto bounds = runtime::boxBounds(part);
      const auto clusters = map_->map().frontierClusters(bounds.min, bounds.max, 3);
      open = std::any_of(clusters.begin(), clusters.end(), [&](const auto& cluster) {
        return cluster.centroid.z() > groundZ_ + 0.5;  // as planExploration's frontiers
      });
    }
    if (open) out.push_back(part);
  }
  return out;
}

void Slei3dStrategy::adoptInspectors(const agent::AgentView& view,
                                     const std::vector<Adoption>& adopt) {
  for (const auto& a : adopt) {
    if (std::any_of(inspectors_.begin(), inspectors_.end(),
                    [&](const InspectorModel& m) { return m.unit == a.inspector; }))
      continue;  // a reply sent again
    InspectorModel model;
    model.unit = a.inspector;
    model.position = a.place;
    model.home = a.place;
    model.since = view.time;
    model.heard = view.time;
    // It learns of its new wait point with the first orders (an announcement when there is
    // nothing to hand out); caric-team's stay at the relay.
    if (options_.variant != SleiVariant::Team && box_ >= 0)
      model.waitAt = waitPointNear(box_, boxFrom_, inspectors_.size());
    inspectors_.push_back(model);
  }
}

void Slei3dStrategy::learnInspected(uint32_t id) {
  if (knownInspected_.insert(id).second && boxFeatures_.count(id)) ++inspectedInBox_;
}

void Slei3dStrategy::dropKnownInspected(std::vector<FeatureTask>& tasks) const {
  const auto known = [&](const FeatureTask& t) { return knownInspected_.count(t.id) > 0; };
  tasks.erase(std::remove_if(tasks.begin(), tasks.end(), known), tasks.end());
}

void Slei3dStrategy::collectDetections(const agent::AgentView& view) {
  // Results it carries (the station's, handed over at its meetings, hold every subgroup's):
  // a feature another explorer found and had inspected is not handed out again (each explorer
  // reports its own first detections). Without this, on slei-c scene seed 1 features already
  // collected were inspected 47 times before 94 % were collected; 19 with it.
  for (const uint32_t id : view.receivedResults)
    learnInspected(id);
  for (const auto& f : view.detectedFeatures) {
    if (knownInspected_.count(f.id)) continue;
    FeatureTask task;
    task.id = f.id;
    task.position = f.position;
    task.normal = f.normal;
    task.viewPosition = view.odometry.position;
    task.viewYaw = view.odometry.yaw;
    task.highPriority = f.highPriority && options_.priorityFirst;
    pending_.push_back(task);
    ++scannedInBox_;
    boxFeatures_.insert(task.id);
  }
}

void Slei3dStrategy::readStatus(const agent::AgentView& view) {
  for (const auto& message : view.messages) {
    if (message.topic != kStatusTopic) continue;
    const auto status = decodeStatus(message.bytes);
    if (!status) continue;
    for (const uint32_t id : status->inspected)
      learnInspected(id);
    for (auto& model : inspectors_) {
      if (names_[model.unit] != message.from) continue;
      model.acknowledged = std::max(model.acknowledged, status->lastOrders);
      // Its own word on where it is: the plan restarts from there, without what is done.
      for (const auto& n : view.neighbours)
        if (n.name == message.from) model.position = n.odometry.position;
      model.since = view.time;
      model.lostUntil = 0.0;  // in contact: found
      model.heard = view.time;
      model.listLeft = status->listLeft;
      dropKnownInspected(model.tasks);
      dropKnownInspected(model.unconfirmed);
      // Done with every list it was sent: what it did not report inspected it skipped (no way
      // to its poses, or no score there), and its results are on board (the status came over
      // the link). Kept, the skipped features had it busy for good in the plans, and a hand-out
      // waits for an inspector free soon: caric-team's explorer3 on slei-c, scene seed 1, came
      // back to the hub where its two inspectors waited idle from 786 s on, and never handed
      // out 24 features.
      if (status->listLeft == 0 && status->lastOrders >= model.sequence) model.tasks.clear();
    }
  }
}

Slei3dStrategy::Plan Slei3dStrategy::planExploration(const agent::AgentView& view) {
  lastPlan_ = view.time;
  const auto& box = boxes_[static_cast<size_t>(box_)];
  const Vec3 here = view.odometry.position;
  // Where and by when it must leave what it does for its station meeting.
  const Vec3 meeting = atMeetHeight(stationMeeting_.place);
  const double deadline = options_.deadlineBound && stationMeeting_.time < kNoMeeting
                              ? stationMeeting_.time - kLeaveMargin
                              : std::numeric_limits<double>::infinity();
  bool notInTime = false;  // something left to explore, not before the meeting
  const auto& grid = map_->grid();
  const double clearance = flight_->requiredClearance(grid);
  // The detector first: the mapped surface of the box it has not passed close to.
  std::vector<planning::InspectionPatch> open = unsweptPatches(box);
  openPatches_ = 0;
  if (open.size() > kPatchesPerPlan) {
    std::stable_sort(open.begin(), open.end(), [&](const auto& a, const auto& b) {
      return (a.centre - here).squaredNorm() < (b.centre - here).squaredNorm();
    });
    open.resize(kPatchesPerPlan);
  }
  openList_ = open;
  sweepRoute_.clear();
  atStopSince_ = -1.0;
  toFrontier_ = false;
  if (!open.empty()) {
    planning::DetectionCoverageOptions coverage;
    coverage.detector = detector_;
    coverage.standoffs = {std::max(1.0, sweepDistance_ - 1.0), sweepDistance_};
    coverage.clearance = clearance;
    coverage.minHeight = 1.0;
    coverage.groundZ = groundZ_;
    // Only places a search can reach: a goal walled off costs a whole search budget per try.
    coverage.reachable =
        &reachable_.from(grid, map_->gridVersion(), here, flight_->searchOptions(grid));
    // Patches without a safe viewpoint now may get one as the map grows: they stay open, and
    // the box counts as explored when no open patch and no frontier has a viewpoint.
    std::vector<uint32_t> uncoverable;
    auto views = planning::detectionViews(open, grid, coverage, &uncoverable);
    // Only patches with a viewpoint count as left to sweep (eq. 9's explored share): a box
    // with surface no safe place sees would never look explored.
    openPatches_ = open.size() - uncoverable.size();
    // Flown nearest first from where the explorer is (a greedy tour), or with `search_depth`
    // the best sequence of that many stops by patches swept per second first (FF3E's search),
    // only as far as it still reaches its station meeting in time (FF3E's bound); the rest
    // waits for the next plan.
    std::vector<Vec3> positions;
    std::vector<double> gains;
    for (const auto& v : views) {
      positions.push_back(v.position);
      gains.push_back(static_cast<double>(v.covered.size()));
    }
    planning::FrontierSearchOptions search;
    search.depth = options_.searchDepth;
    search.dwell = kTurnTime;
    search.travelFactor = kTravelFactor;
    for (const size_t k : planning::deadlineBoundedSearch(
             here, view.time, positions, gains, meeting, deadline, options_.speed, search)) {
      SweepStop stop{views[k].position, views[k].target, {}};
      for (const uint32_t i : views[k].covered)
        stop.keys.push_back(open[i].key);
      sweepRoute_.push_back(std::move(stop));
    }
    if (!sweepRoute_.empty()) {
      exploreAim_ = sweepRoute_.front().target;
      flySweep();
      return Plan::Flying;
    }
    notInTime = !views.empty();
  }
  // Then the roofs, seen from above: the surface it maps there is swept at the next plans.
  if (!roofPass_.empty()) {
    double arrival = view.time;
    Vec3 at = here;
    for (const Vec3& stop : roofPass_)
      arrival += straightTime(at, stop, options_.speed) + kTurnTime, at = stop;
    if (arrival + straightTime(at, meeting, options_.speed) <= deadline) {
      const Vec3 centre(box.center.x(), box.center.y(), roofPass_.front().z());
      for (const Vec3& stop : roofPass_)
        sweepRoute_.push_back({stop, centre, {}});
      exploreAim_ = centre;
      flySweep();
      return Plan::Flying;
    }
    notInTime = true;
  }
  // Then the parts of the box the LiDAR has not mapped: FUEL-style frontier viewpoints.
  const auto bounds = runtime::boxBounds(box);
  const Vec3 margin = Vec3::Constant(kBoxMargin);
  // With `frontier_chunk`, in parts of that many metres: whole, the frontier above a roof was one
  // cluster, flown to once and then never again, and the roof was never seen from above (on
  // slei-a, 19 of 25 features never detected in a run were on roofs the explorers never rose
  // above). Off by default: the parts find more features, but the visits cost more than they
  // bring in a 1200 s slei-a mission (doc/strategies.md, "Exploring").
  auto clusters = map_->map().frontierClusters(bounds.min - margin, bounds.max + margin, 3);
  if (options_.frontierChunk > 0.0)
    clusters = mapping::splitFrontierClusters(clusters, options_.frontierChunk);
  star::RingOptions ring;
  ring.clearance = clearance;
  ring.minZ = groundZ_ + 1.5;
  std::vector<const mapping::FrontierCluster*> order;
  for (const auto& cluster : clusters) {
    const bool visited = std::any_of(unreachable_.begin(), unreachable_.end(), [&](const Vec3& p) {
      return (p - cluster.centroid).norm() < kUnreachableRadius;
    });
    if (!visited && cluster.centroid.z() > groundZ_ + 0.5 && cluster.cells.size() >= 3)
      order.push_back(&cluster);
  }
  std::stable_sort(order.begin(), order.end(), [&](const auto* a, const auto* b) {
    return (a->centroid - here).squaredNorm() < (b->centroid - here).squaredNorm();
  });
  for (const auto* cluster : order) {
    const auto viewpoint = star::bestRingViewpoint(*cluster, grid, ring);
    if (!viewpoint) continue;
    const Vec3& at = viewpoint->pose.position;
    if (view.time + straightTime(here, at, options_.speed) +
            straightTime(at, meeting, options_.speed) >
        deadline) {
      notInTime = true;
      continue;
    }
    toFrontier_ = true;
    exploreAim_ = cluster->centroid;
    flight_->goTo(at, options_.speed);
    return Plan::Flying;
  }
  return notInTime ? Plan::NotBeforeMeeting : Plan::Nothing;
}

// The stop of the station's schedule where the explorer, flying there now, would find the
// station soonest; none when that is not well before the explorer's own meeting, or when,
// the station not there, it could not wait its patience there and still make its own meeting.
// The station drives straight to its next stop after each meeting (it was where this explorer
// met it at the last reply) and leaves a stop once its meeting is held, about the stop's time.
std::optional<Vec3> Slei3dStrategy::earlyStop(const agent::AgentView& view, double* by,
                                              size_t* index) const {
  constexpr double kWorthIt = 20.0;  // s saved at least
  const Vec3 here = view.odometry.position;
  const auto drive = [&](const Vec3& a, const Vec3& b) {
    return std::hypot(a.x() - b.x(), a.y() - b.y()) / options_.plan.stationSpeed;
  };
  std::optional<Vec3> best;
  double soonest = stationMeeting_.time - kWorthIt;
  // A static station stands at its meeting place from the start: before its first reply, when
  // the explorer knows none of its stops, it is met there. (Else a first box explored before
  // the first meeting left its explorer hovering: caric-team on slei-a, scene seed 1, both
  // explorers from about 115 s to 265 s, their meetings due at 300 s.)
  if (staticStation() && stationStops_.empty()) {
    const double at = view.time + straightTime(here, stationMeeting_.place, options_.speed);
    if (at < soonest) *by = at, best = stationMeeting_.place, *index = 0;
    return best;
  }
  double free = lastReply_.time;  // when the station can leave for the next stop
  Vec3 from = lastReply_.place;
  for (size_t k = 0; k < stationStops_.size(); ++k) {
    const auto& stop = stationStops_[k];
    const double arrives = free + drive(from, stop.place);
    const bool own = stop.time >= stationMeeting_.time;
    const double at = std::max(arrives, view.time + straightTime(here, stop.place, options_.speed));
    const bool keepsOwn =
        own || ownMeetingArrival(stop.place, at + kEarlyPatience) <= stationMeeting_.time;
    if ((own || at <= stop.time) && keepsOwn && at < soonest)
      soonest = *by = at, best = stop.place, *index = k;
    if (own) break;
    free = std::max(arrives, stop.time) + kMeetingService;
    from = stop.place;
  }
  return best;
}

// Where to meet a partner at `partner`: the flyable point nearest to it in line of sight (straight
// above a station's corner, an explorer kept clear of a nearby structure hovered 5.4 m from the
// station, beyond the 5 m link; a wait point in unmapped space has no path); `fallback` when the
// map offers nothing within the link's reach. Only points at or above the partner when `above`.
Vec3 Slei3dStrategy::meetingPointNear(const agent::AgentView& view, const Vec3& partner,
                                      const Vec3& fallback, bool above,
                                      const std::optional<Vec3>& toward) const {
  const auto& grid = map_->grid();
  const auto& reachable = reachable_.from(grid, map_->gridVersion(), view.odometry.position,
                                          flight_->searchOptions(grid));
  Vec3 best = fallback;
  const Vec3 aim = toward.value_or(partner);
  double bestDistance = std::numeric_limits<double>::infinity();
  const double step = grid.resolution();
  const int r = static_cast<int>(std::ceil(kApproachReach / step));
  const auto centre = grid.cellOf(partner);
  for (int dz = above ? 0 : -r; dz <= r; ++dz)
    for (int dy = -r; dy <= r; ++dy)
      for (int dx = -r; dx <= r; ++dx) {
        const mapping::Index3 cell = centre + mapping::Index3(dx, dy, dz);
        if (!grid.contains(cell) || !reachable[grid.linear(cell)]) continue;
        const Vec3 p = grid.centre(cell);
        if ((p - partner).norm() >= kApproachReach) continue;
        const double d = (p - aim).norm();
        if (d < bestDistance && planning::lineOfSight(grid, p, partner, false))
          bestDistance = d, best = p;
      }
  return best;
}

Vec3 Slei3dStrategy::atMeetHeight(const Vec3& place) const {
  return Vec3(place.x(), place.y(), groundZ_ + options_.meetHeight);
}

double Slei3dStrategy::ownMeetingArrival(const Vec3& from, double leaving) const {
  return leaving + straightTime(from, atMeetHeight(stationMeeting_.place), options_.speed) +
         kLeaveMargin;
}

Vec3 Slei3dStrategy::stationPoint(const agent::AgentView& view, const Vec3& place) const {
  const Vec3 station(place.x(), place.y(), groundZ_ + kStationAntenna);
  const Vec3 above = atMeetHeight(place);
  const auto* own = subgroupOf(static_cast<uint32_t>(unit_.self));
  if (!staticStation() || !own) return meetingPointNear(view, station, above, true);
  // Every explorer of a static station meets it at the one place: each comes from its own side,
  // kHubSlot out (the explorers in the plan's order around the circle). At one point the
  // lower-priority one backed off to the flight's 4 m separation from the other, out of the
  // link (caric-team on slei-a, scene seed 3: explorer2 hovered 7 m from the station for 143 s
  // while explorer1 waited on the point).
  size_t slot = 0, count = 0;
  for (const auto& s : plan_->subgroups) {
    if (s.station != own->station) continue;
    if (s.explorer == own->explorer) slot = count;
    ++count;
  }
  const double angle = 2.0 * M_PI * static_cast<double>(slot) / static_cast<double>(count);
  const Vec3 side = above + kHubSlot * Vec3(std::cos(angle), std::sin(angle), 0.0);
  return meetingPointNear(view, station, side, true, side);
}

void Slei3dStrategy::goToStation(const agent::AgentView& view, const Vec3& place) {
  lastApproach_ = view.time;
  flight_->goTo(stationPoint(view, place), options_.speed);
}

// Every open patch the detector passes over counts as swept, on the way to a stop as well.
void Slei3dStrategy::markSwept(const agent::AgentView& view) {
  const auto& grid = map_->grid();
  for (const auto& patch : openList_)
    if (!swept_.count(patch.key) &&
        planning::detects(detector_, grid, view.odometry.position, view.odometry.yaw, patch,
                          false) &&
        swept_.insert(patch.key).second)
      ++sweptInBox_;
}

// The sweep route: a stop is passed when all its patches are swept, or given up after the
// heading had time to come round at it (or when the flight there fails); the next stop follows
// without a halt.
void Slei3dStrategy::followSweep(const agent::AgentView& view) {
  if (sweepRoute_.empty()) return;
  auto& stop = sweepRoute_.front();
  const bool swept =
      !stop.keys.empty() && std::all_of(stop.keys.begin(), stop.keys.end(),
                                        [&](uint64_t key) { return swept_.count(key) > 0; });
  const bool there =
      flight_->done() ||
      (options_.sweepThrough && (view.odometry.position - stop.position).norm() < kSweepPassRadius);
  if (!swept && there && atStopSince_ < 0.0) atStopSince_ = view.time;
  const bool givenUp =
      flight_->failed() || (atStopSince_ >= 0.0 && view.time - atStopSince_ >= kTurnTime);
  if (!swept && !givenUp) return;
  for (const uint64_t key : stop.keys)
    if (swept_.insert(key).second) ++sweptInBox_;
  if (stop.keys.empty() && !roofPass_.empty()) roofPass_.erase(roofPass_.begin());
  sweepRoute_.erase(sweepRoute_.begin());
  atStopSince_ = -1.0;
  if (sweepRoute_.empty()) {
    exploreAim_.reset();
    flight_->hover();
    return;
  }
  exploreAim_ = sweepRoute_.front().target;
  flySweep();
}

// One stop at a time, the flight's profile ends at rest at each stop: on slei-c the explorers
// braked to a halt 115-130 times per 1000 s of exploring.
void Slei3dStrategy::flySweep() {
  std::vector<Vec3> route{sweepRoute_.front().position};
  if (!options_.sweepThrough) {
    flight_->goTo(route.front(), options_.speed);
    return;
  }
  if (sweepRoute_.size() > 1) route.push_back(sweepRoute_[1].position);
  flight_->follow(route, options_.speed);
}

// Eq. 9 (planning::predictCompletion): from the explored share of the box and the features
// found and inspected in it while it is explored, else from the inspectors' plans. Without a box
// and with nothing pending: when the last inspector's list ends (0: nothing left at all).
double Slei3dStrategy::predictRemaining(const agent::AgentView& view) const {
  double latest = view.time, earliest = std::numeric_limits<double>::infinity();
  std::vector<Vec3> ends;
  for (const auto& model : inspectors_) {
    const auto plan = predictedPlan(model, view.time);
    // The last pose is its wait point; the one before, its last feature.
    const double end =
        model.tasks.empty() ? view.time : plan.poses[plan.poses.size() - 2].start + kInspectionTime;
    latest = std::max(latest, end);
    earliest = std::min(earliest, end);
    ends.push_back(plan.poses.back().position);
  }
  if (box_ < 0 && pending_.empty()) return latest - view.time;
  // explore-then-inspect's features, all pending when the boxes are done: a pose each, shared
  // by the inspectors, after their lists.
  if (box_ < 0)
    return latest - view.time +
           static_cast<double>(pending_.size()) * (kInspectionTime + kSettle + kPoseTravel) /
               static_cast<double>(std::max<size_t>(1, inspectors_.size()));
  planning::CompletionInputs in;
  const auto& box = boxes_[static_cast<size_t>(std::max(box_, 0))];
  in.boxVolume = box.size.prod();
  // Explored: mapped, and of the mapped surface the share the detector has swept.
  const double swept = static_cast<double>(sweptInBox_), open = static_cast<double>(openPatches_);
  in.exploredVolume = in.boxVolume * boxExploredFraction(box_) *
                      (swept + open > 0.0 ? swept / (swept + open) : 0.0);
  in.featuresScanned = static_cast<int>(scannedInBox_);
  in.featuresInspected = static_cast<int>(inspectedInBox_);
  // Held to the box's end, its features are not inspected while it is explored: the fallback
  // for "none inspected yet" (100 s) set nearly every meeting. slei-a, scene seeds 1-3: 94 % at
  // 903, 799, 764 s against 1009, 848, 790 s.
  in.inspectedAfterExploration = options_.handoutAtBoxEnd;
  in.timeInBox = std::max(0.0, view.time - boxStart_);
  in.explorationFinished = explorationFinished_;
  in.earliestInspectorFinish = std::isfinite(earliest) ? earliest : view.time;
  in.closingTourLength = planning::straightTourLength(view.odometry.position, ends);
  in.now = view.time;
  if (in.exploredVolume == 0.0 && !sweepRoute_.empty()) {
    std::vector<Vec3> stops;
    for (const auto& stop : sweepRoute_)
      stops.push_back(stop.position);
    in.plannedSweepTime = kTravelFactor *
                              planning::straightTourLength(view.odometry.position, stops, false) /
                              options_.speed +
                          kTurnTime * static_cast<double>(stops.size());
  }
  planning::CompletionPredictionOptions options;
  options.explorerSpeed = options_.speed;
  options.maxRemaining = std::max(options.minRemaining, options_.maxMeetingLead);
  return planning::predictCompletion(in, options).remaining;
}

std::vector<Slei3dStrategy::Handout> Slei3dStrategy::splitAtHub(const agent::AgentView& view,
                                                                bool explorationFinished) const {
  if (pending_.empty()) return {};
  std::vector<std::pair<size_t, planning::InspectorPlan>> free;  // model, predicted plan
  for (size_t k = 0; k < inspectors_.size(); ++k)
    if (inspectors_[k].lostUntil <= view.time)
      free.emplace_back(k, predictedPlan(inspectors_[k], view.time));
  if (free.empty()) return {};
  const auto freeAt = [](const auto& f) { return f.second.poses.back().start; };
  std::stable_sort(free.begin(), free.end(),
                   [&](const auto& a, const auto& b) { return freeAt(a) < freeAt(b); });
  const double soonest = freeAt(free.front());
  // Those free within the wait bound of the first share the batch; the others are busy.
  free.erase(std::remove_if(free.begin(), free.end(),
                            [&](const auto& f) { return freeAt(f) > soonest + kMaxHandoutWait; }),
             free.end());
  if (free.size() > pending_.size()) free.resize(pending_.size());
  // The features in a nearest-neighbour tour from the explorer, cut into one run of consecutive
  // features per inspector (no optimisation of anyone's idle time). All of them to the one free
  // soonest, with returns 300 s apart, left slei-a's other inspector idle: 0 to 3 features
  // collected in 1200 s.
  std::vector<FeatureTask> tour;
  std::vector<FeatureTask> left = pending_;
  Vec3 at = view.odometry.position;
  while (!left.empty()) {
    const auto next = std::min_element(left.begin(), left.end(), [&](const auto& a, const auto& b) {
      return (a.position - at).squaredNorm() < (b.position - at).squaredNorm();
    });
    at = next->position;
    tour.push_back(*next);
    left.erase(next);
  }
  std::vector<Handout> planned;
  Vec3 from = view.odometry.position;
  double clock = view.time;
  size_t taken = 0;
  for (size_t i = 0; i < free.size(); ++i) {
    const auto& end = free[i].second.poses.back();
    Handout handout;
    handout.inspector = free[i].first;
    handout.place = meetingPointNear(view, end.position, end.position, false);
    const double arrival = clock + straightTime(from, handout.place, options_.speed);
    if (i == 0 && !explorationFinished && end.start - arrival > kMaxHandoutWait) return {};
    handout.time = std::max(end.start, arrival);  // given up a grace after it
    clock = handout.time;
    from = handout.place;
    const size_t share = (tour.size() - taken) / (free.size() - i);
    handout.orders.tasks.assign(tour.begin() + static_cast<std::ptrdiff_t>(taken),
                                tour.begin() + static_cast<std::ptrdiff_t>(taken + share));
    taken += share;
    planned.push_back(std::move(handout));
  }
  return planned;
}

// A mandatory hand-out (the box explored, or a new box to announce), or one the last box's hold
// let out: an inspector around which SOEI sampled no point (the explorer's map paints an
// inspector waiting out of link, and its neighbourhood with it) gets one candidate, the reachable
// point nearest where its plan ends. Without it SOEI met only the inspectors it had points for
// and gave them the whole box: slei-a, scene seed 2, with `handout_at_box_end`, 26 features to
// `inspector2` (inspected 688 to 800 s) while `inspector1` waited from 433 to 758 s.
void Slei3dStrategy::addPlanEndPoints(const agent::AgentView& view,
                                      const std::vector<planning::InspectorPlan>& plans,
                                      std::vector<planning::InspectorMeetingPoints>* points) const {
  const Vec3 none = Vec3::Constant(std::numeric_limits<double>::quiet_NaN());
  for (size_t i = 0; i < plans.size(); ++i) {
    auto& perPose = (*points)[i];
    if (std::any_of(perPose.begin(), perPose.end(), [](const auto& p) { return !p.empty(); }))
      continue;
    const Vec3 place = meetingPointNear(view, plans[i].poses.back().position, none, false);
    if (place.allFinite()) perPose.back() = {place};
  }
}

std::vector<Slei3dStrategy::Handout> Slei3dStrategy::handToEach(
    const agent::AgentView& view, const std::vector<planning::InspectorPlan>& plans,
    const std::vector<planning::PendingFeature>& features,
    const std::vector<size_t>& modelOf) const {
  std::vector<int> order(plans.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) {
    return plans[static_cast<size_t>(a)].poses.back().start <
           plans[static_cast<size_t>(b)].poses.back().start;
  });
  std::vector<Vec3> places;
  std::vector<double> times;
  Vec3 at = view.odometry.position;
  double clock = view.time;
  for (const int i : order) {
    const auto& end = plans[static_cast<size_t>(i)].poses.back();
    const Vec3 place = meetingPointNear(view, end.position, end.position, false);
    clock = std::max(end.start, clock + straightTime(at, place, options_.speed));
    places.push_back(place);
    times.push_back(clock);
    at = place;
  }
  planning::AllocationModel model;
  model.inspectionTime = kInspectionTime;
  model.inspector.speed = options_.speed;
  const auto allocation =
      planning::allocateFeatures(plans, order, times, features, view.time, model);
  std::vector<Handout> planned;
  for (size_t a = 0; a < allocation.agents.size(); ++a) {
    const auto& agent = allocation.agents[a];
    if (agent.features.empty()) continue;
    Handout handout;
    handout.inspector = modelOf[static_cast<size_t>(agent.inspector)];
    handout.place = places[a];
    handout.time = times[a];
    for (const int f : agent.features)
      handout.orders.tasks.push_back(
          pending_[static_cast<size_t>(features[static_cast<size_t>(f)].id)]);
    planned.push_back(std::move(handout));
  }
  return planned;
}

Slei3dStrategy::Handout Slei3dStrategy::collectionAt(const agent::AgentView& view, size_t k,
                                                     const planning::InspectorPlan& plan) const {
  Handout handout;
  handout.inspector = k;
  const Vec3 end = plan.poses.back().position;
  handout.place = meetingPointNear(view, end, end, false);
  handout.time =
      std::max(plan.poses.back().start,
               view.time + straightTime(view.odometry.position, handout.place, options_.speed));
  handout.collect = true;
  return handout;
}

std::vector<Slei3dStrategy::Handout> Slei3dStrategy::planCollection(
    const agent::AgentView& view) const {
  std::vector<Handout> planned;
  for (size_t k = 0; k < inspectors_.size(); ++k)
    if (inspectors_[k].toCollect(view.time))
      planned.push_back(collectionAt(view, k, predictedPlan(inspectors_[k], view.time)));
  std::stable_sort(planned.begin(), planned.end(),
                   [](const Handout& a, const Handout& b) { return a.time < b.time; });
  return planned;
}

// When a fetch from `at` (at `t`) is over at `place`: flown straight, waiting for the inspector
// there until `ready`, and the exchange.
double Slei3dStrategy::fetchedAt(const Vec3& at, double t, const Vec3& place, double ready) const {
  return std::max(t + straightTime(at, place, options_.speed), ready) + kFetchStop;
}

// Its list presumed worked since its last status (presumeDone): the inspector is where the
// list ends once the time of its features is past. Nearest first, each one kept if the detour
// so far stays within the bound (waiting for a list to end counts).
std::vector<Slei3dStrategy::FetchStop> Slei3dStrategy::fetchOnTheWay(const agent::AgentView& view,
                                                                     const Vec3& to,
                                                                     double* arrival) const {
  std::vector<FetchStop> left;
  for (size_t k = 0; k < inspectors_.size(); ++k)
    if (inspectors_[k].toCollect(view.time))
      left.emplace_back(k, predictedPlan(inspectors_[k], view.time, true));
  std::vector<FetchStop> planned;
  Vec3 at = view.odometry.position;
  double t = view.time;
  const double direct = t + straightTime(at, to, options_.speed);
  const auto endOf = [](const auto& candidate) { return candidate.second.poses.back(); };
  while (!left.empty()) {
    const auto next = std::min_element(left.begin(), left.end(), [&](const auto& a, const auto& b) {
      return (endOf(a).position - at).squaredNorm() < (endOf(b).position - at).squaredNorm();
    });
    const auto end = endOf(*next);
    const double met = fetchedAt(at, t, end.position, end.start);
    if (met + straightTime(end.position, to, options_.speed) - direct <= options_.fetchDetour) {
      planned.push_back(std::move(*next));
      at = end.position;
      t = met;
    }
    left.erase(next);
  }
  *arrival = t + straightTime(at, to, options_.speed);
  return planned;
}

// SOEI (planning/meeting_decision.h): which inspectors to meet with the pending features, in
// which order, where; or not to meet yet.
void Slei3dStrategy::planHandout(const agent::AgentView& view) {
  lastHandout_ = view.time;
  if (inspectors_.empty() || !handouts_.empty()) return;
  // explore-then-inspect: no feature handed out while a box is left to explore.
  if (options_.variant == SleiVariant::ExploreFirst && box_ >= 0) return;
  // Nothing left to explore nor to hand out: the inspectors' results are still to be carried
  // to the station (the last features of a run were inspected and never collected).
  // Not caric-team's: its inspectors bring their results to the hub themselves, and its
  // explorer waiting at the hub for them stood in the others' way (slei-a, scene seed 3:
  // explorer2 held 4.5 m from explorer1 for 206 s, out of the station's link).
  if (box_ < 0 && pending_.empty()) {
    if (options_.variant != SleiVariant::Team) startHandouts(planCollection(view));
    return;
  }
  if (options_.variant == SleiVariant::Team) {
    // caric-team hands out at the hub, on its returns to the station (and once its boxes are
    // done): flying back for every feature found kept it from exploring.
    // (Checked first: the hand-out's meeting point costs a reachability flood of the map.)
    const Vec3 hub = subgroupOf(static_cast<uint32_t>(unit_.self))->firstMeeting.place;
    const bool atHub = (view.odometry.position - hub).norm() <= kHubReach;
    if (atHub || box_ < 0) startHandouts(splitAtHub(view, explorationFinished_ || box_ < 0));
    return;
  }
  // Inspectors missed twice in a row are left out for a while: the explorer does not know
  // where they are, and looking for them again and again kept it from exploring for minutes.
  const auto reachable = [&](const InspectorModel& m) { return m.lostUntil <= view.time; };
  const bool notices =
      std::any_of(inspectors_.begin(), inspectors_.end(),
                  [&](const InspectorModel& m) { return m.waitAt.has_value() && reachable(m); });
  planning::MeetingProblem problem;
  problem.explorer = {view.odometry.position, view.time};
  std::vector<size_t> modelOf;  // problem.inspectors[i] is inspectors_[modelOf[i]]
  for (size_t k = 0; k < inspectors_.size(); ++k)
    if (reachable(inspectors_[k])) {
      modelOf.push_back(k);
      problem.inspectors.push_back(predictedPlan(inspectors_[k], view.time, options_.presumeDone));
    }
  if (problem.inspectors.empty()) return;
  for (size_t i = 0; i < pending_.size(); ++i)
    problem.features.push_back({static_cast<int64_t>(i), pending_[i].position,
                                pending_[i].viewPosition, pending_[i].highPriority});
  problem.explorationFinished = explorationFinished_ || box_ < 0 || notices;
  // `handout_at_box_end`: nothing handed out while the box is left to explore. In-box hand-outs
  // cost slei-a's explorers about a quarter of their time up to 600 s, and their inspectors
  // worked where the explorer swept; held, the 141st feature was found about 150 s sooner.
  // But not for long in its last box: on slei-c (scene seed 1) an explorer sharing the last box
  // held 14 features from about 1000 s to 1510 s while the inspectors idled, and the station
  // waited for them to reach 94 %.
  if (pending_.empty())
    heldSince_ = -1.0;
  else if (heldSince_ < 0.0)
    heldSince_ = view.time;
  const bool heldTooLong = options_.lastBoxHold > 0.0 && nextBox_ < 0 && heldSince_ >= 0.0 &&
                           view.time - heldSince_ >= options_.lastBoxHold;
  if (options_.handoutAtBoxEnd && !problem.explorationFinished && !heldTooLong &&
      std::none_of(pending_.begin(), pending_.end(),
                   [](const FeatureTask& task) { return task.highPriority; }))
    return;
  std::vector<Handout> planned;
  if (!problem.features.empty()) {
    planning::MeetingOptions options;
    options.explorerLimits.speed = options_.speed;
    options.inspectorLimits.speed = options_.speed;
    options.seed = seed_ + static_cast<uint64_t>(std::llround(view.time * 10.0));
    const auto& region = map_->region();
    const planning::MeetingBox box{region.min, region.max};
    const auto space =
        planning::voxelGridMeetingSpace(map_->grid(), flight_->requiredClearance(map_->grid()));
    auto points = planning::sampleInspectorMeetingPoints(problem.inspectors, view.time, box, space,
                                                         options.sampling);
    // Held too long, the features go out even to inspectors SOEI sampled no point around (an
    // inspector waiting out of link, painted on the map): else the hold ended only when the box
    // did (slei-a, scene seed 3: 22 features held from 504 s to 735 s, both inspectors idle).
    if (problem.explorationFinished || heldTooLong)
      addPlanEndPoints(view, problem.inspectors, &points);
    const auto decision = planning::decideMeetings(problem, points, options);
    // No feasible candidate even so (no point near an inspector's plan end either, or every
    // route misses a window): each inspector met where its plan ends, the features split
    // among them. (All of them to the one free soonest left the other idle: slei-a, scene
    // seed 3, with handout_at_box_end, 38 features to one inspector, inspected from 653 to
    // 852 s, while its partner idled from 468 s.)
    if (decision.choice == planning::MeetingChoice::NoFeasibleMeeting &&
        problem.explorationFinished)
      planned = handToEach(view, problem.inspectors, problem.features, modelOf);
    if (decision.choice != planning::MeetingChoice::Meet && planned.empty()) return;
    // The inspectors' windows are predictions, and real flights run late: a meeting the
    // explorer would wait long for (the inspector finishing a long list first) waits while
    // exploring remains; a later decision hands the features out.
    const bool longWait =
        std::any_of(decision.meetings.begin(), decision.meetings.end(),
                    [](const auto& m) { return m.meetingTime - m.arrival > kMaxHandoutWait; });
    if (longWait && !problem.explorationFinished) return;
    for (const auto& meeting : decision.meetings) {
      Handout handout;
      handout.inspector = modelOf[static_cast<size_t>(meeting.inspector)];
      handout.place = meeting.point;
      handout.time = meeting.meetingTime;
      const auto& inspector = problem.inspectors[static_cast<size_t>(meeting.inspector)];
      if (options_.approachPartner)
        handout.partnerAt = inspector.poses[static_cast<size_t>(meeting.pose)].position;
      for (const int64_t i : meeting.featureIds)
        handout.orders.tasks.push_back(pending_[static_cast<size_t>(i)]);
      planned.push_back(std::move(handout));
    }
  } else if (notices) {
    // Nothing to hand out, but a new box to announce: meet each inspector where it stays.
    for (size_t k = 0; k < inspectors_.size(); ++k) {
      if (!inspectors_[k].waitAt || !reachable(inspectors_[k])) continue;
      const auto plan = predictedPlan(inspectors_[k], view.time);
      Handout handout;
      handout.inspector = k;
      handout.place = plan.poses.back().position;
      handout.time = plan.poses.back().start;
      planned.push_back(std::move(handout));
    }
  }
  startHandouts(std::move(planned));
}

// Numbers the orders, takes the handed features off the pending list, and flies to the first.
void Slei3dStrategy::startHandouts(std::vector<Handout> planned) {
  std::vector<uint8_t> handed(pending_.size(), 0);
  for (auto& handout : planned) {
    auto& model = inspectors_[handout.inspector];
    handout.orders.sequence = model.sequence + 1;
    model.sequence = handout.orders.sequence;
    handout.orders.waitAt = model.waitAt;
    for (const auto& task : handout.orders.tasks)
      for (size_t i = 0; i < pending_.size(); ++i)
        if (pending_[i].id == task.id) handed[i] = 1;
  }
  std::vector<FeatureTask> left;
  for (size_t i = 0; i < pending_.size(); ++i)
    if (!handed[i]) left.push_back(pending_[i]);
  pending_ = std::move(left);
  handouts_ = std::move(planned);
  if (handouts_.empty()) return;
  phase_ = ExplorerPhase::ToInspector;
  flight_->goTo(handouts_.front().place, options_.speed);
}

// Above the station, within its charger's range (straight above it: the explorer flies no lower
// than its clearance), until charged; then on with what the last reply said.
agent::AgentCommand Slei3dStrategy::charge(const agent::AgentView& view, uint32_t station) {
  for (const auto& other : view.neighbours)
    if (other.name == names_[station]) stationSeen_ = other.odometry.position;
  if (view.energy > chargeLevel_) {
    chargeLevel_ = view.energy;
    chargeRoseAt_ = view.time;
  }
  // At the charger it keeps its place: on slei-b an explorer of lower priority, pushed away by
  // the other one passing by, charged in bits of 1-6 s for 30 s.
  flight_->standGround(view.time >= chargeFrom_);
  if (view.time < chargeFrom_) {
    flight_->hover();  // the charger is busy: where it met the station, in link
  } else if (view.energy >= kCharged || view.time - chargeRoseAt_ > kChargePatience) {
    charging_ = false;
    flight_->standGround(false);
    if (phase_ == ExplorerPhase::ToBox) flight_->goTo(boxEntry(box_, boxFrom_), options_.speed);
    lastPlan_ = -1e300;
  } else {
    const double above = kChargeHeight * unit_.fleet[unit_.self].battery.chargeRange;
    flight_->goTo(
        Vec3(stationSeen_.x(), stationSeen_.y(), std::max(stationSeen_.z(), groundZ_) + above),
        options_.speed);
  }
  auto flown = fly(view, std::nullopt);
  flown.activity = agent::Activity::Waiting;
  if (stationMeeting_.time < kNoMeeting) flown.stationMeetingTime = stationMeeting_.time;
  return flown;
}

agent::AgentCommand Slei3dStrategy::decideExplorer(const agent::AgentView& view) {
  const auto* subgroup = subgroupOf(static_cast<uint32_t>(unit_.self));
  if (!joined_) {
    joined_ = true;
    for (size_t k = 0; k < subgroup->inspectors.size(); ++k) {
      InspectorModel model;
      model.unit = subgroup->inspectors[k];
      model.since = view.time;
      if (subgroup->box >= 0) model.position = firstWaitPoint(*subgroup, k);
      inspectors_.push_back(model);
    }
    stationMeeting_ = subgroup->firstMeeting;
    enterBox(view, subgroup->box);
    boxFrom_ = subgroup->firstMeeting.place;  // the first wait points' corner (firstWaitPoint)
    // They compute the first wait point from the plan themselves.
    for (size_t k = 0; k < inspectors_.size(); ++k) {
      inspectors_[k].waitAt.reset();
      if (subgroup->box >= 0) inspectors_[k].home = firstWaitPoint(*subgroup, k);
    }
  }
  collectDetections(view);
  readStatus(view);
  dropKnownInspected(pending_);
  agent::AgentCommand command;
  const Vec3 here = view.odometry.position;
  const Vec3 stationPlace = earlyPlace_ ? *earlyPlace_ : stationMeeting_.place;
  const Vec3 meetingPlace = atMeetHeight(stationPlace);

  // The station's reply ends a meeting.
  for (const auto& message : view.messages) {
    if (message.topic != kReplyTopic) continue;
    const auto reply = decodeReply(message.bytes);
    if (!reply || reply->meetingNumber != meetingNumber_) continue;
    ++meetingNumber_;
    stationMeeting_ = reply->next;
    stationStops_ = reply->stops;
    nextBox_ = reply->nextBox;
    lastReply_ = {here, view.time};
    earlyPlace_.reset();
    earlyTried_ = false;
    // Parts the station made of a box.
    const auto learnPart = [&](int32_t box, const std::optional<agent::BoxView>& shape) {
      if (!shape || box < 0) return;
      const auto index = static_cast<size_t>(box);
      if (boxes_.size() <= index) boxes_.resize(index + 1);
      boxes_[index] = *shape;
    };
    learnPart(reply->box, reply->boxShape);
    learnPart(reply->nextBox, reply->nextBoxShape);
    if (reply->box != box_) {
      enterBox(view, reply->box);
    } else {
      phase_ = box_ >= 0 ? ExplorerPhase::Exploring : ExplorerPhase::Done;
      lastPlan_ = -1e300;
    }
    if (reply->dropInspectors) {
      // Presumed lost by the station, which gave its inspectors to others: what it planned to
      // hand them goes back to pending; what they hold, they keep.
      for (const auto& handout : handouts_)
        pending_.insert(pending_.end(), handout.orders.tasks.begin(), handout.orders.tasks.end());
      handouts_.clear();
      inspectors_.clear();
    }
    adoptInspectors(view, reply->adopt);
    hubHandoutDue_ = options_.variant == SleiVariant::Team;
    // [energy]: it charges above the station before it goes on; the station waits for the time
    // the report's level needs.
    if (unit_.fleet[unit_.self].battery.limited() && view.energy < kCharged) {
      charging_ = true;
      chargeFrom_ = reply->chargeFrom;
      chargeLevel_ = view.energy;
      chargeRoseAt_ = std::max(view.time, chargeFrom_);
    }
  }
  if (charging_) return charge(view, subgroup->station);
  // caric-team hands out on each return to its hub, right after the station's reply, before it
  // goes on. Checked only every `handout_period` while exploring, it never came while the
  // explorer was at the hub: slei-a, scene seed 1, its explorers met the station there at 128
  // and 139 s with 16 and 11 features found, and the first feature was handed out at 620 s,
  // once a box was explored. Done with the hand-outs it explores from the hub, also when the
  // reply gave it a new box (going to the box's entry first instead flew the same six slei-a
  // scenes, event for event).
  if (hubHandoutDue_) {
    hubHandoutDue_ = false;
    planHandout(view);
  }

  // Done early: catch the station at one of its stops rather than wait for the meeting.
  // Without inspectors (none in its share, or given to others while it was presumed lost) its
  // features cannot be handed out: they do not hold the box.
  const bool nothingToHand = pending_.empty() || inspectors_.empty();
  const bool boxDone = box_ >= 0 && explorationFinished_ && nothingToHand && handouts_.empty();
  // With its next box reserved it goes on to it as soon as this one is explored: its features
  // still pending are handed out from there, and the meeting stays where and when it was (the
  // report then names the new box).
  if (nextBox_ >= 0 && box_ >= 0 && explorationFinished_ && handouts_.empty() &&
      phase_ == ExplorerPhase::Exploring) {
    const int32_t next = nextBox_;
    nextBox_ = -1;
    enterBox(view, next);
  }
  // caric-team hands out only at its hub: with its last box explored it goes there with what it
  // holds rather than wait for its meeting (at the 300 s returns, slei-c's explorers waited up
  // to 110 s so). At the hub it hands out first (planHandout), then reports the box done.
  const bool teamBoxEnd = options_.variant == SleiVariant::Team && box_ >= 0 &&
                          explorationFinished_ && handouts_.empty() && nextBox_ < 0 &&
                          (here - subgroup->firstMeeting.place).norm() > kHubReach;
  if ((boxDone || teamBoxEnd) &&
      (phase_ == ExplorerPhase::Exploring || phase_ == ExplorerPhase::Done) && !earlyPlace_ &&
      !earlyTried_) {
    earlyTried_ = true;  // once per reply: the schedule it knows grows stale
    earlyPlace_ = earlyStop(view, &earlyBy_, &earlyStop_);
    if (earlyPlace_) {
      phase_ = ExplorerPhase::ToStation;
      goToStation(view, *earlyPlace_);
    }
  }
  // Time to leave for the station? Planned hand-outs wait: their features go back to pending.
  // With no box left and nothing to hand out, it goes on collecting its inspectors' results
  // (planCollection) up to kCollectOverrun past the meeting: they are what the station waits
  // for, and it gives an explorer up only long after its meeting. (Left for every meeting,
  // slei-a, scene seed 2: `explorer2`, without a box from 1008 s, met the station nine times
  // and never came for its inspectors' last 5 results, which their stale lists put after each
  // next meeting.)
  const double atMeeting = view.time + straightTime(here, meetingPlace, options_.speed);
  const bool collecting =
      box_ < 0 && pending_.empty() &&
      (phase_ == ExplorerPhase::ToInspector || phase_ == ExplorerPhase::Done) &&
      std::any_of(inspectors_.begin(), inspectors_.end(),
                  [&](const InspectorModel& m) { return m.toCollect(view.time); }) &&
      atMeeting < stationMeeting_.time + kCollectOverrun;
  const bool busyAway = phase_ == ExplorerPhase::ToBox || phase_ == ExplorerPhase::Exploring ||
                        phase_ == ExplorerPhase::ToInspector || phase_ == ExplorerPhase::Done;
  // `fetch_detour`: results done at its inspectors go with it to this meeting, not the next
  // one. Only with no next box reserved (near the run's end, where the last results set the
  // finish time): at every meeting, the detours took exploring time (slei-c scene seed 2: 94 %
  // at 1627 s against 1447 s without the fetch).
  if (options_.fetchDetour > 0.0 && options_.variant != SleiVariant::Team && nextBox_ < 0 &&
      busyAway && phase_ != ExplorerPhase::ToInspector && !collecting &&
      fetchedFor_ != meetingNumber_ && stationMeeting_.time < kNoMeeting &&
      atMeeting + kLeaveMargin + options_.fetchDetour >= stationMeeting_.time) {
    double via = 0.0;
    auto fetch = fetchOnTheWay(view, meetingPlace, &via);
    // Time to go that way, and still on time for the meeting.
    if (!fetch.empty() && via + kLeaveMargin >= stationMeeting_.time &&
        via <= stationMeeting_.time) {
      fetchedFor_ = meetingNumber_;
      std::vector<Handout> planned;
      for (const auto& [inspector, plan] : fetch)
        planned.push_back(collectionAt(view, inspector, plan));
      startHandouts(std::move(planned));
      fetching_ = true;
    }
  }
  // When it leaves for the station: kLeaveMargin early, flying straight; fetching, once the way
  // via the inspectors left would get it there late.
  double due = atMeeting + kLeaveMargin;
  if (fetching_ && phase_ == ExplorerPhase::ToInspector) {
    Vec3 at = here;
    double t = view.time;
    for (const auto& handout : handouts_) {
      t = fetchedAt(at, t, handout.place, handout.time);
      at = handout.place;
    }
    due = t + straightTime(at, meetingPlace, options_.speed);
  }
  if (busyAway && !collecting && stationMeeting_.time < kNoMeeting && due >= stationMeeting_.time) {
    for (const auto& handout : handouts_)
      pending_.insert(pending_.begin(), handout.orders.tasks.begin(), handout.orders.tasks.end());
    handouts_.clear();
    fetching_ = false;
    phase_ = ExplorerPhase::ToStation;
    goToStation(view, stationPlace);
  }

  const uint32_t stationIndex = subgroup->station;  // its own station (of several, maybe)
  std::optional<Vec3> aim;
  switch (phase_) {
    case ExplorerPhase::ToStation:
    case ExplorerPhase::AtStation: {
      // The station did not come to the early stop: it is late on the schedule the explorer
      // knows (a subgroup before it got a new meeting at the same place, say), so it is still
      // at an earlier stop or on its way from one. The explorer goes back along the station's
      // route, stop by stop, and then to the planned meeting place. (Waiting there instead
      // left a slei-a explorer idle from 190 s to 473 s while the station stood 14 m away.)
      // Nor does it look for it past the time to leave for its own meeting, where the station
      // comes and gives it up a while after (slei-c, scene seed 5: explorer1 looked from 1408 to
      // 1606 s, its meeting at 1455 s; the station, late, waited there from about 1520 s and gave
      // it up at 1582 s; the explorer then waited at its place, unanswered, to 2327 s).
      if (earlyPlace_ && phase_ == ExplorerPhase::ToStation &&
          ownMeetingArrival(here, view.time) >= stationMeeting_.time) {
        earlyPlace_.reset();
        goToStation(view, stationMeeting_.place);
      } else if (earlyPlace_ && phase_ == ExplorerPhase::ToStation &&
                 view.time > earlyBy_ + kEarlyPatience) {
        if (earlyStop_ > 0 && earlyStop_ <= stationStops_.size()) {
          --earlyStop_;
          earlyPlace_ = stationStops_[earlyStop_].place;
          earlyBy_ = view.time + straightTime(here, *earlyPlace_, options_.speed);
          goToStation(view, *earlyPlace_);
        } else {
          earlyPlace_.reset();
          goToStation(view, stationMeeting_.place);
        }
      }
      if (flight_->failed() && view.time - lastApproach_ >= kApproachRetry)
        goToStation(view, stationPlace);
      // Pushed off its point while it waits (it backs off from a higher-priority unit come to
      // meet the station too) and out of link once the station is due: back to the point. The
      // flight holds where it backed off to for good, and a goal reached once is not flown
      // again unless the flight is reset (slei-c, scene seed 1: explorer4 backed off from
      // explorer3 to 5.05 m from the waiting station, was given up at 271 s and hovered there
      // for the rest of the run, exploring nothing).
      const double due = earlyPlace_ ? earlyBy_ : stationMeeting_.time;
      if (flight_->done() && !neighbour(view, stationIndex) && view.time >= due &&
          view.time - lastApproach_ >= kReaimPeriod) {
        lastApproach_ = view.time;
        const Vec3 point = stationPoint(view, stationPlace);
        if ((point - here).norm() > kReaimOffset) {
          flight_->hover();
          flight_->goTo(point, options_.speed);
        }
      }
      if (neighbour(view, stationIndex)) {
        phase_ = ExplorerPhase::AtStation;
        if (view.time - lastSend_ >= kReportPeriod) {
          lastSend_ = view.time;
          Report report;
          report.box = box_;
          // explore-then-inspect moves on with its features still pending.
          report.boxFinished =
              box_ < 0 || (explorationFinished_ &&
                           (nothingToHand || options_.variant == SleiVariant::ExploreFirst));
          report.remaining = predictRemaining(view);
          report.meetingNumber = meetingNumber_;
          if (!report.boxFinished) {
            if (remainderMeeting_ != meetingNumber_) {  // once per meeting: a few map scans
              remainderMeeting_ = meetingNumber_;
              remainder_ = remainderParts();
            }
            report.remainder = remainder_;
          }
          if (unit_.fleet[unit_.self].battery.limited()) report.energy = view.energy;
          send(command, stationIndex, kReportTopic, encode(report));
        }
      }
      command.activity = flight_->done() || phase_ == ExplorerPhase::AtStation
                             ? agent::Activity::Waiting
                             : agent::Activity::TravellingToMeeting;
      break;
    }
    case ExplorerPhase::ToInspector: {
      auto& handout = handouts_.front();
      auto& model = inspectors_[handout.inspector];
      bool over = false;
      if (model.acknowledged >= handout.orders.sequence) {
        for (const auto& task : handout.orders.tasks) {
          model.tasks.push_back(task);
          command.assignedFeatures.push_back(task.id);
        }
        model.missed = 0;
        model.unconfirmed.clear();  // alive: it keeps its list
        // Met once its list should be done: what it reported inspected is on board. With its
        // list done, the rest it skipped: nothing more to wait for. Still at it (flights run
        // later than the plans), it is met again: cleared, its last results stayed with it and
        // the station, told nothing was outstanding, let its explorer go (slei-pre on slei-a,
        // scene seed 3: 34 of 145 features inspected never reached the station).
        if (handout.collect && model.listLeft == 0) model.tasks.clear();
        if (handout.orders.waitAt) {
          model.home = *handout.orders.waitAt;  // it goes there once its list is done
          model.waitAt.reset();
        }
        over = true;
      } else if (view.time > handout.time + options_.meetingGrace || flight_->failed()) {
        // Not met in time (or no way there): the features go back to the pending list, and the
        // orders are sent again next time (same sequence number). The inspector was not where
        // its plan said: it is presumed at its wait point, where it goes when it finds no way
        // to a pose (sampling the same wrong place again failed for the rest of a run).
        --model.sequence;
        model.position = model.home;
        model.since = view.time;
        model.unconfirmed.insert(model.unconfirmed.end(), model.tasks.begin(), model.tasks.end());
        model.tasks.clear();
        if (++model.missed >= 2) {
          model.missed = 0;
          model.lostUntil = view.time + kLostFor;
          // Not heard for long either: presumed failed (the paper's inspector failure), what it
          // was given and has not reported inspected goes to the others. If it is alive after
          // all, both may inspect a feature: time lost, no feature. (Missed twice alone was
          // common for live inspectors: handing their lists out again cost 14 features in a
          // slei-a run.)
          if (view.time - model.heard > kPresumedFailed) {
            pending_.insert(pending_.end(), model.unconfirmed.begin(), model.unconfirmed.end());
            model.unconfirmed.clear();
          }
        }
        pending_.insert(pending_.begin(), handout.orders.tasks.begin(), handout.orders.tasks.end());
        flight_->hover();
        over = true;
      } else if (handout.partnerAt && !handout.approached && flight_->done() &&
                 view.time >= handout.time + kApproachAfter && !neighbour(view, model.unit)) {
        // The point lies within the link's range of where the inspector should be, less 1 m;
        // a wait point or own view a metre or two from that left the two just out of range
        // (an inspector hovering 5.3-5.5 m away for the whole grace, in slei-a runs).
        handout.approached = true;
        const Vec3 to = approachPoint(here, *handout.partnerAt, kApproachStop);
        if ((to - here).norm() > 0.0) flight_->goTo(to, options_.speed);
      } else if (neighbour(view, model.unit) && view.time - lastSend_ >= kReportPeriod / 2) {
        lastSend_ = view.time;
        send(command, model.unit, kOrdersTopic, encode(handout.orders));
      }
      if (over) {
        handouts_.erase(handouts_.begin());
        if (!handouts_.empty()) {
          flight_->goTo(handouts_.front().place, options_.speed);
        } else {
          fetching_ = false;
          phase_ = box_ >= 0 ? ExplorerPhase::Exploring : ExplorerPhase::Done;
          lastPlan_ = -1e300;
        }
      }
      command.activity =
          flight_->done() ? agent::Activity::Waiting : agent::Activity::TravellingToMeeting;
      break;
    }
    case ExplorerPhase::ToBox:
      if (flight_->done() || flight_->failed()) {
        phase_ = ExplorerPhase::Exploring;
        boxStart_ = view.time;
        lastPlan_ = -1e300;
      }
      command.activity = agent::Activity::Exploring;
      break;
    case ExplorerPhase::Exploring: {
      markSwept(view);
      followSweep(view);
      // A frontier cluster flown to (or given up) is not chosen again: if its frontier is still
      // there, another viewpoint will not do better soon.
      if (toFrontier_ && (flight_->failed() || flight_->done())) {
        if (exploreAim_) unreachable_.push_back(*exploreAim_);
        toFrontier_ = false;
        exploreAim_.reset();
        flight_->hover();
      }
      const bool idle = sweepRoute_.empty() && !toFrontier_;
      const bool due = view.time - lastPlan_ >= (idle ? 0.5 : kReplanPeriod);
      if (!explorationFinished_ && due) {
        const Plan plan = planExploration(view);
        if (plan == Plan::Nothing && flight_->done())
          explorationFinished_ = true;  // no open patch nor frontier with a viewpoint
        if (plan == Plan::NotBeforeMeeting) {
          // Nothing it can do and still be on time: on to the meeting (FF3E's bound; no
          // hand-out is under way while it explores).
          phase_ = ExplorerPhase::ToStation;
          goToStation(view, stationMeeting_.place);
        }
      }
      aim = exploreAim_;
      command.activity = agent::Activity::Exploring;
      break;
    }
    case ExplorerPhase::Done:
      // At a static station's hub it waits above its own side of the station, out of the way:
      // where it last handed out it stood on the inspectors' circle, and on its side at their
      // height it held an inspector with a list at the hub for 380 s (caric-team on slei-a,
      // scene seed 1: the flight keeps lower-priority units 4 m off). Its meetings bring it down.
      if (staticStation()) {
        if (!hubSlot_) hubSlot_ = stationPoint(view, stationMeeting_.place) + kParkAbove;
        flight_->goTo(*hubSlot_, options_.speed);
      }
      command.activity = agent::Activity::Waiting;
      break;
  }
  if ((phase_ == ExplorerPhase::Exploring || phase_ == ExplorerPhase::Done) &&
      view.time - lastHandout_ >= options_.handoutPeriod)
    planHandout(view);
  auto flown = fly(view, aim);
  if (stationMeeting_.time < kNoMeeting) flown.stationMeetingTime = stationMeeting_.time;
  flown.activity = command.activity;
  flown.assignedFeatures = std::move(command.assignedFeatures);
  flown.messages = std::move(command.messages);
  return flown;
}

}  // namespace coinspect::strategies::slei
