// slei3d, an explorer: explore the box, hand features to the inspectors, meet the station.
#include <algorithm>
#include <cmath>
#include <limits>

#include "coinspect/planning/coverage.h"
#include "coinspect/planning/meeting_decision.h"
#include "coinspect/planning/slei_schedule.h"
#include "coinspect/strategies/runtime/box_geometry.h"
#include "coinspect/strategies/slei/slei3d_strategy.h"
#include "coinspect/strategies/star/star_explore.h"

namespace coinspect::strategies::slei {

namespace {

constexpr double kReplanPeriod = 2.0;       // s between exploration plans while flying
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
constexpr double kNoMeeting = 1e299;

double straightTime(const Vec3& a, const Vec3& b, double speed) {
  return kTravelFactor * (a - b).norm() / speed;
}

}  // namespace

planning::InspectorPlan Slei3dStrategy::predictedPlan(const InspectorModel& model,
                                                      double now) const {
  planning::InspectorPlan plan;
  plan.id = static_cast<int>(model.unit);
  double t = std::max(now, model.since);
  Vec3 at = model.position;
  for (const auto& task : model.tasks) {
    const double start = std::max(now, t + straightTime(at, task.viewPosition, options_.speed));
    plan.poses.push_back({task.viewPosition, start, start + kInspectionTime + kSettle});
    t = plan.poses.back().end;
    at = task.viewPosition;
  }
  if (plan.poses.empty())
    plan.poses.push_back({at, t, planning::kOpenWindowEnd});
  else
    plan.poses.back().end = planning::kOpenWindowEnd;  // it stays at its last pose
  return plan;
}

void Slei3dStrategy::enterBox(const agent::AgentView& view, int32_t box) {
  box_ = box;
  boxStart_ = view.time;
  explorationFinished_ = false;
  scannedInBox_ = 0;
  inspectedInBox_ = 0;
  boxFeatures_.clear();
  sweptInBox_ = 0;
  sweeping_.clear();
  openPatches_ = 0;
  unreachable_.clear();
  exploreAim_.reset();
  if (box < 0) {
    phase_ = ExplorerPhase::Done;
    return;
  }
  const Vec3 corner = boxCorner(boxes_[static_cast<size_t>(box)], options_.plan.cornerOffset,
                                groundZ_ + options_.exploreHeight, view.odometry.position);
  phase_ = ExplorerPhase::ToBox;
  flight_->goTo(corner, options_.speed);
  // Every inspector of the subgroup waits off the new corner once its list is done; it learns
  // of it at its next orders.
  for (size_t k = 0; k < inspectors_.size(); ++k)
    inspectors_[k].waitAt =
        awayFromBox(boxes_[static_cast<size_t>(box)], corner, 2.5 * static_cast<double>(k + 1),
                    groundZ_ + options_.waitHeight);
}

void Slei3dStrategy::collectDetections(const agent::AgentView& view) {
  for (const auto& f : view.detectedFeatures) {
    FeatureTask task;
    task.id = f.id;
    task.position = f.position;
    task.normal = f.normal;
    task.viewPosition = view.odometry.position;
    task.viewYaw = view.odometry.yaw;
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
      if (reportedInspected_.insert(id).second && boxFeatures_.count(id)) ++inspectedInBox_;
    for (auto& model : inspectors_) {
      if (names_[model.unit] != message.from) continue;
      model.acknowledged = std::max(model.acknowledged, status->lastOrders);
      // Its own word on where it is: the plan restarts from there, without what is done.
      for (const auto& n : view.neighbours)
        if (n.name == message.from) model.position = n.odometry.position;
      model.since = view.time;
      model.tasks.erase(
          std::remove_if(model.tasks.begin(), model.tasks.end(),
                         [&](const FeatureTask& t) { return reportedInspected_.count(t.id) > 0; }),
          model.tasks.end());
    }
  }
}

bool Slei3dStrategy::planExploration(const agent::AgentView& view) {
  lastPlan_ = view.time;
  const auto& box = boxes_[static_cast<size_t>(box_)];
  const Vec3 here = view.odometry.position;
  const auto& grid = map_->grid();
  const double clearance = flight_->requiredClearance(grid);
  // The detector first: the mapped surface of the box it has not passed close to.
  std::vector<planning::InspectionPatch> open;
  for (const auto& patch :
       planning::groupSurface(map_->surfaceNearBoxes({box}, kSurfaceNearBox), kPatchSize))
    if (!swept_.count(patch.key)) open.push_back(patch);
  openPatches_ = open.size();
  if (open.size() > kPatchesPerPlan) {
    std::stable_sort(open.begin(), open.end(), [&](const auto& a, const auto& b) {
      return (a.centre - here).squaredNorm() < (b.centre - here).squaredNorm();
    });
    open.resize(kPatchesPerPlan);
  }
  if (!open.empty()) {
    planning::CoverageOptions coverage;
    coverage.distance = options_.sweepDistance;
    coverage.maxDistance = options_.sweepDistance + 1.0;
    coverage.unknownHides = false;  // mapped surface: rays reached it through that space
    coverage.halfFov = 0.6;         // inside the detector's +-45 deg x +-30 deg
    coverage.clearance = clearance;
    coverage.minHeight = 1.0;
    coverage.groundZ = groundZ_;
    // Patches without a safe viewpoint now may get one as the map grows: they stay open, and
    // the box counts as explored when no open patch and no frontier has a viewpoint.
    const auto views = planning::coverPatches(open, grid, coverage);
    if (!views.empty()) {
      const auto nearest =
          std::min_element(views.begin(), views.end(), [&](const auto& a, const auto& b) {
            return (a.camera - here).squaredNorm() < (b.camera - here).squaredNorm();
          });
      sweeping_.clear();
      for (const uint32_t i : nearest->covered)
        sweeping_.push_back(open[i].key);
      exploreAim_ = nearest->target;
      flight_->goTo(nearest->camera, options_.speed);
      return true;
    }
  }
  // Then the parts of the box the LiDAR has not mapped: FUEL-style frontier viewpoints.
  const auto bounds = runtime::boxBounds(box);
  const Vec3 margin = Vec3::Constant(kBoxMargin);
  const auto clusters = map_->map().frontierClusters(bounds.min - margin, bounds.max + margin, 3);
  star::RingOptions ring;
  ring.clearance = clearance;
  ring.minZ = groundZ_ + 1.5;
  std::vector<const mapping::FrontierCluster*> order;
  for (const auto& cluster : clusters) {
    const bool visited = std::any_of(unreachable_.begin(), unreachable_.end(), [&](const Vec3& p) {
      return (p - cluster.centroid).norm() < kUnreachableRadius;
    });
    if (!visited && cluster.centroid.z() > groundZ_ + 0.5) order.push_back(&cluster);
  }
  std::stable_sort(order.begin(), order.end(), [&](const auto* a, const auto* b) {
    return (a->centroid - here).squaredNorm() < (b->centroid - here).squaredNorm();
  });
  for (const auto* cluster : order) {
    const auto viewpoint = star::bestRingViewpoint(*cluster, grid, ring);
    if (!viewpoint) continue;
    sweeping_.clear();
    exploreAim_ = cluster->centroid;
    flight_->goTo(viewpoint->pose.position, options_.speed);
    return true;
  }
  return false;
}

// Eq. 9 (planning::predictCompletion): from the explored share of the box and the features
// found and inspected in it while it is explored, else from the inspectors' plans. Without a box
// and with nothing pending: when the last inspector's list ends (0: nothing left at all).
double Slei3dStrategy::predictRemaining(const agent::AgentView& view) const {
  double latest = view.time, earliest = std::numeric_limits<double>::infinity();
  std::vector<Vec3> ends;
  for (const auto& model : inspectors_) {
    const auto plan = predictedPlan(model, view.time);
    const double end = model.tasks.empty() ? view.time : plan.poses.back().start + kInspectionTime;
    latest = std::max(latest, end);
    earliest = std::min(earliest, end);
    ends.push_back(plan.poses.back().position);
  }
  if (box_ < 0 && pending_.empty()) return latest - view.time;
  planning::CompletionInputs in;
  const auto& box = boxes_[static_cast<size_t>(std::max(box_, 0))];
  in.boxVolume = box.size.prod();
  // Explored: mapped, and of the mapped surface the share the detector has swept.
  const double swept = static_cast<double>(sweptInBox_), open = static_cast<double>(openPatches_);
  in.exploredVolume = in.boxVolume * boxExploredFraction(box_) *
                      (swept + open > 0.0 ? swept / (swept + open) : 0.0);
  in.featuresScanned = static_cast<int>(scannedInBox_);
  in.featuresInspected = static_cast<int>(inspectedInBox_);
  in.timeInBox = std::max(0.0, view.time - boxStart_);
  in.explorationFinished = explorationFinished_;
  in.earliestInspectorFinish = std::isfinite(earliest) ? earliest : view.time;
  in.closingTourLength = planning::straightTourLength(view.odometry.position, ends);
  in.now = view.time;
  planning::CompletionPredictionOptions options;
  options.explorerSpeed = options_.speed;
  return planning::predictCompletion(in, options).remaining;
}

// SOEI (planning/meeting_decision.h): which inspectors to meet with the pending features, in
// which order, where; or not to meet yet.
void Slei3dStrategy::planHandout(const agent::AgentView& view) {
  lastHandout_ = view.time;
  if (inspectors_.empty() || !handouts_.empty()) return;
  const bool notices = std::any_of(inspectors_.begin(), inspectors_.end(),
                                   [](const InspectorModel& m) { return m.waitAt.has_value(); });
  planning::MeetingProblem problem;
  problem.explorer = {view.odometry.position, view.time};
  for (const auto& model : inspectors_)
    problem.inspectors.push_back(predictedPlan(model, view.time));
  for (size_t i = 0; i < pending_.size(); ++i)
    problem.features.push_back(
        {static_cast<int64_t>(i), pending_[i].position, pending_[i].viewPosition});
  problem.explorationFinished = explorationFinished_ || box_ < 0 || notices;
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
    const auto decision = planning::decideMeetings(problem, box, space, options);
    if (decision.choice != planning::MeetingChoice::Meet) return;
    for (const auto& meeting : decision.meetings) {
      Handout handout;
      handout.inspector = static_cast<size_t>(meeting.inspector);
      handout.place = meeting.point;
      handout.time = meeting.meetingTime;
      for (const int64_t i : meeting.featureIds)
        handout.orders.tasks.push_back(pending_[static_cast<size_t>(i)]);
      planned.push_back(std::move(handout));
    }
  } else if (notices) {
    // Nothing to hand out, but a new box to announce: meet each inspector where it stays.
    for (size_t k = 0; k < inspectors_.size(); ++k) {
      if (!inspectors_[k].waitAt) continue;
      const auto plan = predictedPlan(inspectors_[k], view.time);
      Handout handout;
      handout.inspector = k;
      handout.place = plan.poses.back().position;
      handout.time = plan.poses.back().start;
      planned.push_back(std::move(handout));
    }
  }
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
    for (auto& model : inspectors_)
      model.waitAt.reset();  // they compute the first one from the plan themselves
  }
  collectDetections(view);
  readStatus(view);
  agent::AgentCommand command;
  const Vec3 here = view.odometry.position;
  // Right above the station's corner: UAVs hover about 4.5 m up there, within the 5 m link of a
  // station on the ground (1 m off the corner they were out of range).
  const Vec3 meetingPlace(stationMeeting_.place.x(), stationMeeting_.place.y(),
                          groundZ_ + options_.meetHeight);

  // The station's reply ends a meeting.
  for (const auto& message : view.messages) {
    if (message.topic != kReplyTopic) continue;
    const auto reply = decodeReply(message.bytes);
    if (!reply || reply->meetingNumber != meetingNumber_) continue;
    ++meetingNumber_;
    stationMeeting_ = reply->next;
    if (reply->box != box_) {
      enterBox(view, reply->box);
    } else {
      phase_ = box_ >= 0 ? ExplorerPhase::Exploring : ExplorerPhase::Done;
      lastPlan_ = -1e300;
    }
  }

  // Time to leave for the station? Planned hand-outs wait: their features go back to pending.
  const bool busyAway = phase_ == ExplorerPhase::ToBox || phase_ == ExplorerPhase::Exploring ||
                        phase_ == ExplorerPhase::ToInspector || phase_ == ExplorerPhase::Done;
  if (busyAway && stationMeeting_.time < kNoMeeting &&
      view.time + straightTime(here, meetingPlace, options_.speed) + kLeaveMargin >=
          stationMeeting_.time) {
    for (const auto& handout : handouts_)
      pending_.insert(pending_.begin(), handout.orders.tasks.begin(), handout.orders.tasks.end());
    handouts_.clear();
    phase_ = ExplorerPhase::ToStation;
    flight_->goTo(meetingPlace, options_.speed);
  }

  const auto station = std::find_if(unit_.fleet.begin(), unit_.fleet.end(), [](const auto& m) {
    return m.role == agent::Role::GroundStation;
  });
  const auto stationIndex = static_cast<uint32_t>(station - unit_.fleet.begin());
  std::optional<Vec3> aim;
  switch (phase_) {
    case ExplorerPhase::ToStation:
    case ExplorerPhase::AtStation: {
      if (flight_->failed()) flight_->goTo(meetingPlace + Vec3(0, 0, 1.5), options_.speed);
      if (station != unit_.fleet.end() && neighbour(view, stationIndex)) {
        phase_ = ExplorerPhase::AtStation;
        if (view.time - lastSend_ >= kReportPeriod) {
          lastSend_ = view.time;
          Report report;
          report.box = box_;
          report.boxFinished = box_ < 0 || (explorationFinished_ && pending_.empty());
          report.remaining = predictRemaining(view);
          report.meetingNumber = meetingNumber_;
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
        if (handout.orders.waitAt) model.waitAt.reset();
        over = true;
      } else if (view.time > handout.time + options_.meetingGrace || flight_->failed()) {
        // Not met in time (or no way there): the features go back to the pending list, and the
        // orders are sent again next time (same sequence number).
        --model.sequence;
        pending_.insert(pending_.begin(), handout.orders.tasks.begin(), handout.orders.tasks.end());
        flight_->hover();
        over = true;
      } else if (neighbour(view, model.unit) && view.time - lastSend_ >= kReportPeriod / 2) {
        lastSend_ = view.time;
        send(command, model.unit, kOrdersTopic, encode(handout.orders));
      }
      if (over) {
        handouts_.erase(handouts_.begin());
        if (!handouts_.empty()) {
          flight_->goTo(handouts_.front().place, options_.speed);
        } else {
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
      // A viewpoint reached (or given up) sweeps its patches; a frontier cluster flown to is
      // not chosen again: if its frontier is still there, another viewpoint will not do better
      // soon.
      if (flight_->failed() || (flight_->done() && exploreAim_)) {
        if (sweeping_.empty() && exploreAim_) unreachable_.push_back(*exploreAim_);
        for (const uint64_t key : sweeping_)
          if (swept_.insert(key).second) ++sweptInBox_;
        sweeping_.clear();
        exploreAim_.reset();
        flight_->hover();
      }
      const bool due = view.time - lastPlan_ >= (flight_->done() ? 0.5 : kReplanPeriod);
      if (!explorationFinished_ && due && !planExploration(view) && flight_->done())
        explorationFinished_ = true;  // no open patch nor frontier with a viewpoint
      aim = exploreAim_;
      command.activity = agent::Activity::Exploring;
      break;
    }
    case ExplorerPhase::Done:
      command.activity = agent::Activity::Waiting;
      break;
  }
  if ((phase_ == ExplorerPhase::Exploring || phase_ == ExplorerPhase::Done) &&
      view.time - lastHandout_ >= options_.handoutPeriod)
    planHandout(view);
  auto flown = fly(view, aim);
  flown.activity = command.activity;
  flown.assignedFeatures = std::move(command.assignedFeatures);
  flown.messages = std::move(command.messages);
  return flown;
}

}  // namespace coinspect::strategies::slei
