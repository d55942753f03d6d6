#include "coinspect/sensing/score_log.h"

#include <algorithm>
#include <cmath>

#include "coinspect/core/error.h"

namespace coinspect::sensing {

namespace {

double sumInOrder(const std::vector<float>& values) {
  double total = 0.0;
  for (float v : values)
    total += v;
  return total;
}

}  // namespace

ScoreLog::ScoreLog(size_t pointCount) : best_(pointCount, 0.0f) {}

bool ScoreLog::record(uint32_t index, double score) {
  COINSPECT_ASSERT(index < best_.size());
  if (!(score >= kCountThreshold)) return false;
  const float value = static_cast<float>(score);
  float& best = best_[index];
  if (!(best < value)) return false;  // the reference replaces only on strictly better
  if (best == 0.0f) ++detected_;
  best = value;
  return true;
}

size_t ScoreLog::record(const std::vector<PointScore>& capture) {
  size_t improved = 0;
  for (const PointScore& ps : capture) {
    if (ps.counted && record(ps.index, ps.score)) ++improved;
  }
  return improved;
}

double ScoreLog::totalScore() const {
  return sumInOrder(best_);
}

void ScoreLog::clear() {
  std::fill(best_.begin(), best_.end(), 0.0f);
  detected_ = 0;
}

GroundStationTally::GroundStationTally(size_t pointCount, ScoringMode mode)
    : value_(pointCount, 0.0f), mode_(mode) {}

size_t GroundStationTally::merge(const ScoreLog& log, bool uavAlive) {
  COINSPECT_ASSERT(log.size() == value_.size());
  if (!uavAlive && mode_ == ScoringMode::Strict) return 0;
  size_t improved = 0;
  const std::vector<float>& bests = log.bests();
  for (size_t i = 0; i < value_.size(); ++i) {
    if (value_[i] < bests[i]) {
      if (value_[i] == 0.0f) ++detected_;
      value_[i] = bests[i];
      ++improved;
    }
  }
  return improved;
}

size_t GroundStationTally::mergePoints(const ScoreLog& log, const std::vector<uint32_t>& points,
                                       bool uavAlive) {
  COINSPECT_ASSERT(log.size() == value_.size());
  if (!uavAlive && mode_ == ScoringMode::Strict) return 0;
  size_t improved = 0;
  for (const uint32_t i : points) {
    COINSPECT_ASSERT(i < value_.size());
    const float best = log.best(i);
    if (value_[i] < best) {
      if (value_[i] == 0.0f) ++detected_;
      value_[i] = best;
      ++improved;
    }
  }
  return improved;
}

double GroundStationTally::totalScore() const {
  return sumInOrder(value_);
}

long long tallyMergeTicks(double physicsStep) {
  return std::max(1LL, std::llround(kTallyMergePeriod / physicsStep));
}

bool capturesWhenCrashed(ScoringMode mode) {
  return mode == ScoringMode::Caric;
}

bool scoresAfterMissionEnd(ScoringMode mode) {
  return mode == ScoringMode::Caric;
}

double capturePeriod(double triggerInterval, double physicsStep, ScoringMode mode) {
  if (mode == ScoringMode::Strict || physicsStep <= 0.0) return triggerInterval;
  // Steps counted exactly (the reference's clock is integer nanoseconds): the first step count
  // whose elapsed time is strictly greater than the interval. The 1e-9 absorbs the rounding of
  // interval / step when it is a whole number in exact arithmetic.
  const double steps = std::floor(triggerInterval / physicsStep + 1e-9) + 1.0;
  return steps * physicsStep;
}

}  // namespace coinspect::sensing
