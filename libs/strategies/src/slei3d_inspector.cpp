// slei3d, an inspector: fly the list of features it was given, each from its own view in front
// of it, then from the pose where its explorer detected it, until the camera has inspected it;
// then wait where it was told.
#include <algorithm>
#include <cmath>

#include "coinspect/planning/viewpoint.h"
#include "coinspect/strategies/slei/slei3d_strategy.h"

namespace coinspect::strategies::slei {

namespace {

constexpr double kStatusPeriod = 1.0;   // s between status messages while the explorer is near
constexpr double kRetryWait = 20.0;     // s before trying again to reach a wait point
constexpr double kViewDistance = 3.0;   // m from a feature to its own inspection view
constexpr double kViewMinHeight = 1.5;  // m above the ground, the lowest camera of that view
// With `oblique_views`, off the normal when its whole line is blocked (a fin or a neighbouring
// wall in front of the feature): at 55 deg the camera still resolves r_des at kViewDistance,
// where the detection pose, the next try, often sees the feature at a grazing angle.
constexpr double kObliqueViews[] = {30.0 * M_PI / 180.0, 55.0 * M_PI / 180.0};

}  // namespace

agent::AgentCommand Slei3dStrategy::decideInspector(const agent::AgentView& view) {
  const auto* subgroup = subgroupOf(static_cast<uint32_t>(unit_.self));
  if (!waitAt_ && subgroup->box >= 0) {
    const auto& ids = subgroup->inspectors;
    const auto k = static_cast<size_t>(
        std::find(ids.begin(), ids.end(), static_cast<uint32_t>(unit_.self)) - ids.begin());
    waitAt_ = firstWaitPoint(*subgroup, k);
  }
  if (!myExplorer_) myExplorer_ = subgroup->explorer;
  // Its own inspections; caric-team's inspectors also the results they were handed (a feature
  // in either is skipped, and the status lists it). Measured both ways on slei-c
  // (doc/slei3d-runs.md): the skip slowed slei3d (94 % collected at a mean 1584 s on six scenes
  // with it, 1500 s without), whose explorers, carrying the same results, hand none of them out
  // anyway; caric-team reached 94 % at 1614, 1752, 1673 s on scene seeds 1-3 with it, at 1804 s,
  // not within 1950 s and 1633 s without.
  for (const uint32_t f : view.inspectedFeatures)
    inspected_.insert(f);
  if (options_.variant == SleiVariant::Team)
    for (const uint32_t f : view.receivedResults)
      inspected_.insert(f);
  for (const auto& message : view.messages) {
    if (message.topic != kOrdersTopic) continue;
    const auto orders = decodeOrders(message.bytes);
    const auto from = std::find(names_.begin(), names_.end(), message.from);
    if (!orders || from == names_.end()) continue;
    // Orders from another explorer: its own was lost and the station gave it to this one
    // (adoption), which numbers its orders afresh.
    const auto sender = static_cast<uint32_t>(from - names_.begin());
    if (sender != *myExplorer_) {
      if (unit_.fleet[sender].role != agent::Role::Explorer) continue;
      myExplorer_ = sender;
      lastOrders_ = 0;
    }
    if (orders->sequence <= lastOrders_) continue;
    lastOrders_ = orders->sequence;
    for (const auto& task : orders->tasks)
      if (!inspected_.count(task.id)) tasks_.push_back(task);
    if (orders->waitAt) afterList_ = orders->waitAt;
  }
  // Off the list: inspected, waited for too long at its pose, or no way there. With nothing
  // left the inspector goes to its wait point, which its explorer knows: an explorer that
  // planned to meet it at its last pose missed it whenever that pose was not where the
  // inspector ended up (a pose it found no way to, or a stale report of where it was).
  // The explorer's detection pose often sees the feature at a grazing angle (the detector only
  // needs it to face the explorer), where the camera scores nothing: of the features handed out
  // and never inspected in slei-a runs, most had been detected with the line of sight within
  // 6 deg of the surface. The inspector first tries its own view in front of the feature, then
  // the detection pose, each with the full patience; then it skips the feature.
  const auto drop = [&] {
    atTaskSince_.reset();
    if (ownView_) {  // the detection pose next
      ownView_ = false;
      taskPose_ = tasks_.front().viewPosition;
      flight_->hover();
      return;
    }
    tasks_.erase(tasks_.begin());
    taskPose_.reset();
    taskPoseFor_ = -1;
  };
  while (!tasks_.empty() && inspected_.count(tasks_.front().id)) {
    ownView_ = false;
    drop();
  }
  if (!tasks_.empty() && atTaskSince_ && view.time - *atTaskSince_ > options_.inspectPatience)
    drop();
  if (!tasks_.empty() && flight_->failed()) {
    drop();
    flight_->hover();
  }
  if (!tasks_.empty() && taskPoseFor_ != static_cast<int64_t>(tasks_.front().id)) {
    taskPoseFor_ = tasks_.front().id;
    bool free = false;
    const Vec3 own = ownViewpoint(tasks_.front(), &free);
    ownView_ = free;
    taskPose_ = free ? own : tasks_.front().viewPosition;
  }
  if (tasks_.empty() && afterList_) {
    waitAt_ = afterList_;
    afterList_.reset();
  }

  agent::AgentCommand command;
  std::optional<Vec3> aim;
  if (!tasks_.empty()) {
    const auto& task = tasks_.front();
    // The flight ignores a goal it is flying to or holds at: done() stays true at the pose, and
    // the patience runs from the first decision there.
    flight_->goTo(*taskPose_, options_.speed);
    if (flight_->done() && !atTaskSince_) atTaskSince_ = view.time;
    aim = task.position;
    command.activity = agent::Activity::Inspecting;
  } else {
    // A wait point it finds no way to is tried again only now and then (every try is a whole
    // path search budget); it hovers where it is meanwhile.
    if (flight_->failed() && !flight_->done()) {
      flight_->hover();
      retryWaitAt_ = view.time + kRetryWait;
    }
    if (waitAt_ && view.time >= retryWaitAt_) flight_->goTo(*waitAt_, options_.speed);
    command.activity = agent::Activity::Waiting;
  }

  const uint32_t explorer = *myExplorer_;
  if (neighbour(view, explorer) && view.time - lastStatus_ >= kStatusPeriod) {
    lastStatus_ = view.time;
    Status status;
    status.lastOrders = lastOrders_;
    status.inspected.assign(inspected_.begin(), inspected_.end());
    status.listLeft = static_cast<uint32_t>(tasks_.size());
    send(command, explorer, kStatusTopic, encode(status));
  }
  auto flown = fly(view, aim);
  flown.activity = command.activity;
  flown.messages = std::move(command.messages);
  return flown;
}

// In front of the feature along its normal, kViewDistance out (well inside the distance at
// which the camera resolves r_des), the camera lifted to a safe height and the body pushed out of
// blocked cells of its map; `free` false when no traversable place was found.
Vec3 Slei3dStrategy::ownViewpoint(const FeatureTask& task, bool* free) const {
  planning::ViewpointOptions o;
  o.optics = unit_.optics;
  o.distance = std::min(kViewDistance, planning::fullResolutionDistance(unit_.optics));
  o.cameraOffset = unit_.camera.positionInBody;
  o.minHeight = groundZ_ + kViewMinHeight;
  o.grid = &map_->grid();
  o.pathOptions = flight_->searchOptions(map_->grid());
  if (options_.obliqueViews)
    o.obliqueAngles.assign(std::begin(kObliqueViews), std::end(kObliqueViews));
  const auto viewpoint = planning::makeViewpoint({task.position, task.normal}, o);
  *free = viewpoint.free;
  return viewpoint.body;
}

}  // namespace coinspect::strategies::slei
