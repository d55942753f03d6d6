// Evaluates a recorded run: scores every recorded capture again from its recorded state (body
// pose, velocities, gimbal, occluding UAVs) with the scenario's geometry, replays the links, the
// deaths and the ground station's merges at the ticks the live mission merged, and compares the
// result with the recorded tally. doc/evaluation.md explains what is computed and why it is
// exact.
#pragma once

#include <functional>
#include <string>

#include "coinspect/eval/run_evaluation.h"
#include "coinspect/record/rawlog_reader.h"
#include "coinspect/sensing/inspection_scorer.h"
#include "coinspect/world/scenario.h"

namespace coinspect::eval {

struct EvaluationParams {
  sensing::ScoringMode scoring = sensing::ScoringMode::Caric;  // the run's [mission] scoring
  double physicsStep = 0.0025;    // the run's [mission] physics_step, s
  double progressPeriod = 1.0;    // simulated s between progress callbacks
  std::string source = "rawlog";  // names the rawlog in error messages
};

struct EvaluationProgress {
  double time = 0.0;   // simulated s reached
  double score = 0.0;  // re-scored Q so far
  size_t detected = 0;
  size_t pointCount = 0;
  double missionStart = -1.0;  // s, once the mission-start event was read (else negative)
};
using ProgressCallback = std::function<void(const EvaluationProgress&)>;

// Reads `reader` from where it stands (just after the header) to its end or to the damage; the
// result's `read` is the reader's final status. `scenario` must be the one the run was flown in
// (the caller checks the content hash). Throws InputError (naming params.source) when the
// rawlog names a unit the scenario's fleet does not have.
RunEvaluation evaluateRun(record::RawlogReader& reader, const world::Scenario& scenario,
                          const EvaluationParams& params, const ProgressCallback& progress = {});

}  // namespace coinspect::eval
