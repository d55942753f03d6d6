#include "mission_features.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "coinspect/core/error.h"

namespace coinspect::sim {

namespace {

constexpr double kNever = std::numeric_limits<double>::quiet_NaN();

std::string featureDetail(uint32_t feature) {
  return "feature " + std::to_string(feature);
}

bool isInspector(agent::Role role) {
  return role == agent::Role::Photographer;
}

}  // namespace

namespace {

const char* const kPriorityKey = "[features] priority_boxes";

}  // namespace

std::vector<uint8_t> priorityBoxFlags(const std::vector<std::string>& names,
                                      const world::Scenario& scenario, const std::string& source) {
  std::vector<uint8_t> urgent(scenario.boxes.size(), 0);
  for (const std::string& name : names) {
    const auto box = std::find_if(scenario.boxes.begin(), scenario.boxes.end(),
                                  [&](const world::OrientedBox& b) { return b.name == name; });
    if (box == scenario.boxes.end()) {
      std::string known;
      for (const auto& b : scenario.boxes)
        known += (known.empty() ? "" : ", ") + b.name;
      throw InputError(source, kPriorityKey,
                       "no box '" + name + "' in the scenario (boxes: " + known + ")");
    }
    urgent[static_cast<size_t>(box - scenario.boxes.begin())] = 1;
  }
  return urgent;
}

std::vector<uint8_t> highPriorityFeatures(const std::vector<uint8_t>& urgentBoxes,
                                          const world::Scenario& scenario,
                                          const std::string& source) {
  if (std::find(urgentBoxes.begin(), urgentBoxes.end(), 1) == urgentBoxes.end()) return {};
  std::vector<uint8_t> high(scenario.interestPoints.size(), 0);
  for (size_t b = 0; b < urgentBoxes.size(); ++b) {
    if (!urgentBoxes[b]) continue;
    const auto& box = scenario.boxes[b];
    size_t inside = 0;
    for (size_t f = 0; f < high.size(); ++f)
      if (box.contains(scenario.interestPoints[f].position)) high[f] = 1, ++inside;
    if (inside == 0)
      throw InputError(source, kPriorityKey, "box '" + box.name + "' holds no feature");
  }
  return high;
}

std::vector<double> explorerDetectRanges(const std::vector<double>& ranges, double fallback,
                                         const world::Scenario& scenario,
                                         const std::string& source) {
  std::vector<double> out(scenario.fleet.size(), 0.0);
  size_t explorers = 0;
  for (size_t i = 0; i < out.size(); ++i) {
    if (scenario.fleet[i].role != world::UnitRole::Explorer) continue;
    out[i] = explorers < ranges.size() ? ranges[explorers] : fallback;
    ++explorers;
  }
  if (!ranges.empty() && ranges.size() != explorers)
    throw InputError(source, "[features] explorer_ranges",
                     std::to_string(ranges.size()) + " ranges for " + std::to_string(explorers) +
                         " explorers: give one per explorer, in fleet order");
  return out;
}

FeatureTracker::FeatureTracker(const FeatureConfig& config, const world::InterestPointSet& features,
                               std::vector<uint8_t> highPriority, std::vector<std::string> names,
                               std::vector<agent::Role> roles, std::vector<double> ranges,
                               EventSink sink)
    : config_(config),
      features_(features),
      highPriority_(std::move(highPriority)),
      names_(std::move(names)),
      roles_(std::move(roles)),
      ranges_(std::move(ranges)),
      sensor_(config.sensor),
      sink_(std::move(sink)),
      carried_(names_.size(), features.size()),
      meetings_(names_.size(), config.meetingGap),
      knownByUnit_(names_.size()),
      discoveredAt_(features.size(), kNever),
      assignedAt_(features.size(), kNever),
      inspectedAt_(features.size(), kNever),
      collectedAt_(features.size(), kNever),
      pendingDetections_(names_.size()),
      pendingInspected_(names_.size()),
      pendingReceived_(names_.size()),
      detectedCount_(names_.size(), 0),
      inspectedCount_(names_.size(), 0),
      activity_(names_.size(), agent::Activity::Unreported),
      activitySince_(names_.size(), 0.0),
      counting_(names_.size(), 0),
      activitySeconds_(names_.size()) {
  promises_.resize(names_.size());
  stations_ =
      static_cast<size_t>(std::count(roles_.begin(), roles_.end(), agent::Role::GroundStation));
  for (size_t i = 0; i < names_.size(); ++i) {
    // Only inspectors keep a timer; the others get an empty one (no feature to index).
    timers_.emplace_back(isInspector(roles_[i]) ? features.size() : 0, config.inspectTime);
    if (roles_[i] == agent::Role::Explorer) knownByUnit_[i].assign(features.size(), 0);
  }
}

void FeatureTracker::start(double time) {
  for (size_t i = 0; i < names_.size(); ++i) {
    counting_[i] = 1;
    activitySince_[i] = time;
    // Changes before the clock starts are not events: the timeline (coinspect plot-timeline)
    // begins with what each unit reports when the clock starts.
    sink_("activity-changed", names_[i], agent::toString(activity_[i]));
  }
}

void FeatureTracker::addActivityTime(size_t unit, double time) {
  if (!counting_[unit]) return;
  activitySeconds_[unit][static_cast<size_t>(activity_[unit])] += time - activitySince_[unit];
  activitySince_[unit] = time;
}

void FeatureTracker::detect(size_t unit, double time, const vehicle::VehicleState& state,
                            const world::RayCaster& caster) {
  sensor_.range = ranges_[unit];
  sensing::detectFeatures(sensor_, state.position, state.yaw, features_, caster, found_);
  auto& known = knownByUnit_[unit];
  for (const uint32_t f : found_) {
    if (known[f]) continue;
    known[f] = 1;
    ++detectedCount_[unit];
    pendingDetections_[unit].push_back(
        {f, features_[f].position, features_[f].normal, time, isHighPriority(f)});
    if (std::isnan(discoveredAt_[f])) {
      discoveredAt_[f] = time;
      sink_("feature-detected", names_[unit], featureDetail(f));
    }
  }
}

void FeatureTracker::capture(size_t unit, double time,
                             const std::vector<sensing::PointScore>& scores) {
  if (!isInspector(roles_[unit])) return;
  counted_.clear();
  for (const auto& s : scores)
    if (s.seen && s.score >= config_.inspectScore) counted_.push_back(s.index);
  completed_.clear();
  timers_[unit].capture(time, counted_, completed_);
  for (const uint32_t f : completed_) {
    ++inspectedCount_[unit];
    pendingInspected_[unit].push_back(f);
    carried_.add(static_cast<uint32_t>(unit), f);
    if (std::isnan(inspectedAt_[f])) inspectedAt_[f] = time;
    sink_("feature-inspected", names_[unit], featureDetail(f));
  }
}

bool FeatureTracker::exchange(double time, const comms::LinkMatrix& links,
                              const std::vector<bool>& alive) {
  for (const auto& [a, b] : meetings_.update(time, links)) {
    if (!alive[a] || !alive[b]) continue;
    const auto ra = roles_[a], rb = roles_[b];
    const auto pair = [&](agent::Role x, agent::Role y) {
      return (ra == x && rb == y) || (ra == y && rb == x);
    };
    if (pair(agent::Role::GroundStation, agent::Role::Explorer))
      ++meetingsGcsExplorer_;
    else if (pair(agent::Role::Explorer, agent::Role::Photographer))
      ++meetingsExplorerInspector_;
    else
      ++meetingsOther_;
    sink_("meeting", names_[a], names_[b]);
  }
  if (stations_ > 0) {
    const double tolerance = config_.punctualityTolerance;
    for (size_t e = 0; e < promises_.size(); ++e) {
      if (!promises_[e] || !alive[e]) continue;
      bool linked = false;
      for (size_t g = 0; g < roles_.size() && !linked; ++g)
        linked = roles_[g] == agent::Role::GroundStation && alive[g] && g != e &&
                 links.linked(static_cast<uint32_t>(e), static_cast<uint32_t>(g));
      auto& promise = *promises_[e];
      if (!linked) promise.unlinked = true;
      if (!linked || promise.kept || promise.late) continue;
      if (time < promise.time - tolerance)
        promise.early = promise.early || promise.unlinked;
      else if (std::abs(time - promise.time) <= tolerance)
        promise.kept = true;
      else if (time > promise.time + tolerance)
        promise.late = true;
    }
  }
  for (const auto& handover : carried_.exchange(links, alive)) {
    pendingReceived_[handover.unit].push_back(handover.item);
    // Several stations: a result counts once, when the first of them receives it.
    if (roles_[handover.unit] != agent::Role::GroundStation ||
        !std::isnan(collectedAt_[handover.item]))
      continue;
    collectedAt_[handover.item] = time;
    ++collected_;
    sink_("feature-collected", names_[handover.unit], featureDetail(handover.item));
  }
  if (finishedAt_ || stations_ == 0 || collected_ < features_.size()) return false;
  finishedAt_ = time;
  return true;
}

void FeatureTracker::unitDied(size_t unit, double time) {
  addActivityTime(unit, time);
  counting_[unit] = 0;
  carried_.drop(static_cast<uint32_t>(unit));
}

size_t FeatureTracker::command(size_t unit, double time, const agent::AgentCommand& command) {
  if (command.activity && *command.activity != activity_[unit]) {
    addActivityTime(unit, time);
    activity_[unit] = *command.activity;
    if (counting_[unit]) sink_("activity-changed", names_[unit], agent::toString(activity_[unit]));
  }
  if (command.stationMeetingTime && std::isfinite(*command.stationMeetingTime) &&
      roles_[unit] == agent::Role::Explorer &&
      (!promises_[unit] || promises_[unit]->time != *command.stationMeetingTime)) {
    if (promises_[unit]) settle(*promises_[unit], time, true, settled_);
    promises_[unit] = Promise{*command.stationMeetingTime};
  }
  size_t bad = 0;
  for (const uint32_t f : command.assignedFeatures) {
    if (f >= features_.size()) {
      ++bad;
      continue;
    }
    if (std::isnan(assignedAt_[f])) assignedAt_[f] = time;
  }
  return bad;
}

void FeatureTracker::fill(size_t unit, agent::AgentView& view) {
  view.detectedFeatures = std::move(pendingDetections_[unit]);
  pendingDetections_[unit].clear();
  view.inspectedFeatures = std::move(pendingInspected_[unit]);
  pendingInspected_[unit].clear();
  view.receivedResults = std::move(pendingReceived_[unit]);
  pendingReceived_[unit].clear();
}

void FeatureTracker::settle(const Promise& promise, double now, bool replaced,
                            PromiseCounts& counts) const {
  const double tolerance = config_.punctualityTolerance;
  if (promise.kept)
    ++counts.onTime;
  else if (promise.late)
    ++counts.late;
  else if (now > promise.time + tolerance)
    ++counts.missed;
  else if (replaced && now < promise.time - tolerance)
    ++(promise.early ? counts.early : counts.rescheduled);
  // Else still open at the end, or replaced inside its window: not counted.
}

FeatureSummary FeatureTracker::summary(double now, double startTime) const {
  FeatureSummary out;
  out.enabled = true;
  out.total = features_.size();
  const auto onClock = [startTime](const std::vector<double>& at, size_t& count) {
    std::vector<double> times(at.size(), kNever);
    for (size_t f = 0; f < at.size(); ++f) {
      if (std::isnan(at[f])) continue;
      times[f] = std::max(0.0, at[f] - startTime);
      ++count;
    }
    return times;
  };
  out.discoveredAt = onClock(discoveredAt_, out.discovered);
  out.assignedAt = onClock(assignedAt_, out.assigned);
  out.inspectedAt = onClock(inspectedAt_, out.inspected);
  out.collectedAt = onClock(collectedAt_, out.collected);
  out.highPriority.assign(features_.size(), 0);
  double lastPriority = 0.0;
  for (size_t f = 0; f < features_.size(); ++f) {
    if (!isHighPriority(f)) continue;
    out.highPriority[f] = 1;
    ++out.priorityTotal;
    if (std::isnan(out.collectedAt[f])) continue;
    ++out.priorityCollected;
    lastPriority = std::max(lastPriority, out.collectedAt[f]);
  }
  if (out.priorityTotal > 0 && out.priorityCollected == out.priorityTotal)
    out.priorityFinishTime = lastPriority;
  if (finishedAt_) out.finishTime = std::max(0.0, *finishedAt_ - startTime);
  out.meetingsGcsExplorer = meetingsGcsExplorer_;
  out.meetingsExplorerInspector = meetingsExplorerInspector_;
  out.meetingsOther = meetingsOther_;
  PromiseCounts promises = settled_;
  for (const auto& promise : promises_)
    if (promise) settle(*promise, now, false, promises);
  out.promisesOnTime = promises.onTime;
  out.promisesEarly = promises.early;
  out.promisesLate = promises.late;
  out.promisesMissed = promises.missed;
  out.promisesRescheduled = promises.rescheduled;
  for (size_t i = 0; i < names_.size(); ++i) {
    FeatureUnitSummary u;
    u.activitySeconds = activitySeconds_[i];
    if (counting_[i])
      u.activitySeconds[static_cast<size_t>(activity_[i])] += now - activitySince_[i];
    u.detected = detectedCount_[i];
    u.inspected = inspectedCount_[i];
    u.held = carried_.heldCount(static_cast<uint32_t>(i));
    out.units.push_back(u);
  }
  return out;
}

}  // namespace coinspect::sim
