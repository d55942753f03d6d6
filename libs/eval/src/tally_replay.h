// The ground station's side of a recorded run, replayed: per-unit score logs, who is alive, who
// is linked to the station, and the station's merges at the mission's topology ticks.
//
// The live mission (libs/sim, stepOnce) merges at every topology tick k (k % P == 0,
// P = sensing::tallyMergeTicks(step)) after that tick's link update and deaths and before that
// tick's captures. A rawlog is written in that same order, so the replay merges lazily: before an
// object of tick k it runs the merges due at the topology ticks before k (and at k itself when
// the object comes after the merge in the tick's order). Between two objects nothing changes, so
// one merge stands for all the topology ticks in between.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "coinspect/eval/run_evaluation.h"
#include "coinspect/sensing/score_log.h"
#include "coinspect/world/scenario.h"

namespace coinspect::eval::detail {

class TallyReplay {
 public:
  TallyReplay(const world::Scenario& scenario, sensing::ScoringMode mode, double physicsStep);

  size_t unitCount() const { return units_.size(); }
  // Index in the fleet, or npos.
  static constexpr size_t npos = static_cast<size_t>(-1);
  size_t unitIndex(const std::string& name) const;

  // Runs the merges due before tick `tick`, and at `tick` itself when `afterMerge` (the object
  // being read comes after the merge in the tick's order).
  void advanceTo(long long tick, bool afterMerge);

  // A link between two units appeared or disappeared at `time`.
  void setLinked(size_t a, size_t b, bool linked, double time);
  // The unit died at `time` (later deaths of the same unit are ignored, as in the mission).
  void kill(size_t unit, double time);
  bool alive(size_t unit) const { return units_[unit].alive; }
  // Scores of one capture into the unit's log (ScoreLog::record); the next merge that sees the
  // unit linked takes it when the log improved.
  void recordCapture(size_t unit, const std::vector<sensing::PointScore>& scores);

  const sensing::GroundStationTally& tally() const { return tally_; }
  // tally().totalScore(), kept from the last merge that improved it (summing every point at
  // every look would cost more than the merges).
  double score() const { return score_; }
  const std::vector<CoverageSample>& coverage() const { return coverage_; }
  const sensing::ScoreLog& log(size_t unit) const { return units_[unit].log; }
  // Time linked with the station up to `endTime` (open links count until then).
  double lineOfSightTime(size_t unit, double endTime) const;
  double deathTime(size_t unit) const { return units_[unit].deathTime; }

 private:
  struct Unit {
    std::string name;
    bool uav = false;
    bool alive = true;
    double deathTime = 0.0;
    sensing::ScoreLog log;
    // Points its log improved since its last merge: only they can improve the tally, so the
    // merge looks at them alone (GroundStationTally::mergePoints).
    std::vector<uint32_t> changed;
    std::vector<uint8_t> isChanged;  // per point: listed in `changed`
    bool linkedToStation = false;
    double linkedSince = 0.0;
    double lineOfSight = 0.0;  // closed link intervals, s
  };

  void mergeAt(long long tick);

  std::vector<Unit> units_;
  size_t station_ = npos;  // the first ground station of the fleet, as in the mission
  sensing::GroundStationTally tally_;
  double score_ = 0.0;
  double step_;
  long long period_;         // ticks between merges
  long long nextMerge_ = 0;  // the first topology tick not merged yet
  std::vector<CoverageSample> coverage_;
};

}  // namespace coinspect::eval::detail
