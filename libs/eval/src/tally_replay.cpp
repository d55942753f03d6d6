#include "tally_replay.h"

namespace coinspect::eval::detail {

TallyReplay::TallyReplay(const world::Scenario& scenario, sensing::ScoringMode mode,
                         double physicsStep)
    : tally_(scenario.interestPoints.size(), mode),
      step_(physicsStep),
      period_(sensing::tallyMergeTicks(physicsStep)) {
  const size_t pointCount = scenario.interestPoints.size();
  units_.resize(scenario.fleet.size());
  for (size_t i = 0; i < units_.size(); ++i) {
    const auto& spec = scenario.fleet[i];
    units_[i].name = spec.name;
    units_[i].uav = spec.role != world::UnitRole::GroundStation;
    units_[i].log = sensing::ScoreLog(pointCount);
    units_[i].isChanged.assign(pointCount, 0);
    if (!units_[i].uav && station_ == npos) station_ = i;
  }
}

size_t TallyReplay::unitIndex(const std::string& name) const {
  for (size_t i = 0; i < units_.size(); ++i)
    if (units_[i].name == name) return i;
  return npos;
}

void TallyReplay::advanceTo(long long tick, bool afterMerge) {
  const long long last = afterMerge ? tick : tick - 1;
  if (last < nextMerge_) return;
  // Nothing changed since the previous object: the merges at every topology tick up to `last`
  // give what the first of them gives.
  mergeAt(nextMerge_);
  nextMerge_ = (last / period_ + 1) * period_;
}

void TallyReplay::mergeAt(long long tick) {
  if (station_ == npos || !units_[station_].alive) return;
  size_t improved = 0;
  for (auto& unit : units_) {
    if (!unit.uav || !unit.linkedToStation || unit.changed.empty()) continue;
    improved += tally_.mergePoints(unit.log, unit.changed, unit.alive);
    for (const uint32_t point : unit.changed)
      unit.isChanged[point] = 0;
    unit.changed.clear();
  }
  if (improved == 0) return;
  score_ = tally_.totalScore();
  coverage_.push_back({static_cast<double>(tick) * step_, score_, tally_.detectedCount()});
}

void TallyReplay::setLinked(size_t a, size_t b, bool linked, double time) {
  if (station_ == npos || (a != station_ && b != station_) || a == b) return;
  Unit& other = units_[a == station_ ? b : a];
  if (other.linkedToStation == linked) return;
  other.linkedToStation = linked;
  if (linked)
    other.linkedSince = time;
  else
    other.lineOfSight += time - other.linkedSince;
}

void TallyReplay::kill(size_t unit, double time) {
  if (!units_[unit].alive) return;
  units_[unit].alive = false;
  units_[unit].deathTime = time;
}

void TallyReplay::recordCapture(size_t unit, const std::vector<sensing::PointScore>& scores) {
  Unit& u = units_[unit];
  for (const auto& s : scores) {  // ScoreLog::record(scores), point by point
    if (!s.counted || !u.log.record(s.index, s.score) || u.isChanged[s.index]) continue;
    u.isChanged[s.index] = 1;
    u.changed.push_back(s.index);
  }
}

double TallyReplay::lineOfSightTime(size_t unit, double endTime) const {
  const Unit& u = units_[unit];
  return u.lineOfSight + (u.linkedToStation ? endTime - u.linkedSince : 0.0);
}

}  // namespace coinspect::eval::detail
