// What evaluating a recorded run yields (evaluate_run.h): the re-scored ground-station tally next
// to the recorded one, and what the rawlog alone tells about the run. doc/evaluation.md.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "coinspect/record/rawlog_reader.h"
#include "coinspect/world/fleet.h"

namespace coinspect::eval {

// Counts of q_blur and q_res of seen points in 10 equal bins over [0, 1]; bin b holds values in
// [b / 10, (b + 1) / 10), the last bin includes 1.
inline constexpr size_t kQualityBins = 10;
struct QualityHistogram {
  std::array<uint64_t, kQualityBins> qBlur{};
  std::array<uint64_t, kQualityBins> qRes{};
  uint64_t samples() const;  // seen points counted (the same for both histograms)
  void add(double qBlurValue, double qResValue);
  void add(const QualityHistogram& other);
};

// The ground station's tally after one merge that improved it.
struct CoverageSample {
  double time = 0.0;   // simulated s (the merge's topology tick)
  double score = 0.0;  // Q, the sum of the tally's values
  size_t detected = 0;
};

struct UnitEvaluation {
  std::string name;
  world::UnitRole role = world::UnitRole::Photographer;
  uint64_t captures = 0;  // captures scored into the unit's log
  // Captures of the unit after its death in strict mode: the live run does not take them, so
  // they are not scored (a consistent rawlog has none).
  uint64_t capturesIgnored = 0;
  size_t detected = 0;           // points in its own log (best >= the count threshold)
  double ownScore = 0.0;         // sum of its own log
  size_t holdsGcsValue = 0;      // points whose tally value (> 0) equals this unit's best
  size_t onlyDetector = 0;       // points detected by this unit's log and by no other unit's
  QualityHistogram quality;      // seen points of its captures
  double lineOfSightTime = 0.0;  // s linked with the ground station (UAVs; 0 for stations)
  bool alive = true;             // no death event read
  double deathTime = 0.0;        // s, when !alive
};

struct RunEvaluation {
  size_t pointCount = 0;
  std::string scoring;  // "caric" or "strict"

  // Re-scored ground-station tally (every capture scored again from its recorded state).
  std::vector<float> values;  // per interest point, index order
  double score = 0.0;         // Q
  size_t detected = 0;

  // Recorded tally: the point values of every gcs.tally record applied in order; score and
  // detected of the last one (0 when there is none).
  std::vector<float> recordedValues;
  double recordedScore = 0.0;
  size_t recordedDetected = 0;
  uint64_t tallyRecords = 0;
  // Points whose re-scored and recorded values differ (0: exactly equal, value by value), and
  // gcs.tally records whose totals differ from the re-scored tally at the same instant.
  size_t valueMismatches = 0;
  uint64_t tallyRecordMismatches = 0;
  bool equal() const {
    return valueMismatches == 0 && tallyRecordMismatches == 0 && score == recordedScore &&
           detected == recordedDetected;
  }

  std::vector<CoverageSample> coverage;  // one per improving merge, in time order
  std::vector<UnitEvaluation> units;     // fleet order
  QualityHistogram quality;              // all captures

  // Agreement of the recorded scored points with the re-scored ones: captures compared, points
  // that differ in any field or appear on one side only, and captures with at least one.
  uint64_t capturesCompared = 0;
  uint64_t pointMismatches = 0;
  uint64_t capturesMismatched = 0;
  // Version 0 captures carry no body state: their recorded points are used as they are.
  uint64_t capturesNotRescored = 0;

  double endTime = 0.0;       // simulated s of the last object read
  bool missionEnded = false;  // a mission end (or no-takeoff) event was read
  record::ReadStatus read;    // the reader's status: clean, or objects read and damage offset
};

}  // namespace coinspect::eval
