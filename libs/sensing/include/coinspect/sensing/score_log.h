// The per-UAV log of best captures and the ground station's tally, as the reference keeps them
// (gazebo_ppcom_plugin.cpp: InPoLog per node, TallyScore at the GCS), plus the reference's
// timing and crash quirks as explicit policy functions.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "coinspect/sensing/inspection_scorer.h"

namespace coinspect::sensing {

// Best score per interest point ever captured by one UAV (kept on board). Only captures with
// score >= kCountThreshold are recorded. Values are stored in single precision, as the
// reference stores them in the PCL intensity field, so totals match it to the last digit.
class ScoreLog {
 public:
  ScoreLog() = default;
  explicit ScoreLog(size_t pointCount);

  size_t size() const { return best_.size(); }
  // Keeps `score` when it reaches the threshold and beats the current best; true if kept.
  bool record(uint32_t index, double score);
  // Records every counted entry of one capture; returns how many points improved.
  size_t record(const std::vector<PointScore>& capture);

  float best(uint32_t index) const { return best_[index]; }
  const std::vector<float>& bests() const { return best_; }
  size_t detectedCount() const { return detected_; }
  // Sum of the best scores, accumulated in double in index order like the reference.
  double totalScore() const;
  void clear();

 private:
  std::vector<float> best_;
  size_t detected_ = 0;
};

// The ground station's view: per point, the max over every log it has merged.
class GroundStationTally {
 public:
  GroundStationTally() = default;
  explicit GroundStationTally(size_t pointCount, ScoringMode mode = ScoringMode::Caric);

  // Merges the log of a UAV that is in line of sight of the GCS (the caller decides that, at
  // every tick). In caric mode the log of a crashed UAV is merged like any other (the reference
  // has no alive check); in strict mode a crashed UAV no longer transmits and is skipped.
  // Returns how many points improved.
  size_t merge(const ScoreLog& log, bool uavAlive = true);
  // The same merge restricted to the listed points: equal to merge(log, uavAlive) when every
  // other point of `log` is already <= the tally (e.g. `points` lists what the log improved
  // since it was last merged). For the evaluator of recorded runs, which merges often.
  size_t mergePoints(const ScoreLog& log, const std::vector<uint32_t>& points,
                     bool uavAlive = true);

  float value(uint32_t index) const { return value_[index]; }
  const std::vector<float>& values() const { return value_; }
  size_t size() const { return value_.size(); }
  // Mission score Q: sum over points, in double, in index order.
  double totalScore() const;
  // Points with a value > 0.
  size_t detectedCount() const { return detected_; }
  ScoringMode mode() const { return mode_; }

 private:
  std::vector<float> value_;
  size_t detected_ = 0;
  ScoringMode mode_ = ScoringMode::Caric;
};

// The ground station merges the logs of the UAVs in its line of sight at every topology update
// (the reference's 50 Hz), i.e. every tallyMergeTicks(step) physics steps: max(1, round(0.02 /
// step)). The mission and the evaluator of recorded runs (libs/eval) share it, so that a replay
// merges at exactly the ticks the live run did.
inline constexpr double kTallyMergePeriod = 0.02;  // s
long long tallyMergeTicks(double physicsStep);

// Reference quirks as policy (doc/scoring.md, "Quirks"):
// A crashed UAV keeps capturing in caric mode (nothing stops its camera); not in strict mode.
bool capturesWhenCrashed(ScoringMode mode);
// Scoring continues after the mission time budget in caric mode; stops in strict mode.
bool scoresAfterMissionEnd(ScoringMode mode);
// Time between automatic captures: the reference fires when the time since the last capture is
// strictly greater than the trigger interval, checked at every physics step, so the period is
// the first multiple of the step beyond the interval (0.1025 s for 0.1 s and 2.5 ms steps).
// Strict mode returns the interval itself. physicsStep <= 0 means continuous time.
double capturePeriod(double triggerInterval, double physicsStep, ScoringMode mode);

}  // namespace coinspect::sensing
