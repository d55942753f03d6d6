// What `coinspect eval` prints and writes (doc/evaluation.md, "Outputs"): the text report, and
// with --out eval.json and coverage.csv.
#pragma once

#include <cstdio>
#include <filesystem>
#include <string>

#include "coinspect/eval/run_evaluation.h"
#include "recorded_run.h"

namespace coinspect::app {

// Wall-clock figures, reported but never part of the comparison.
struct EvalTiming {
  double wallTime = 0.0;  // s
  double simTime = 0.0;   // simulated s read
  double simPerWall() const { return wallTime > 0.0 ? simTime / wallTime : 0.0; }
};

// The text report: recorded and re-scored score ("equal" / "DIFFERENT"), units, histograms,
// line-of-sight times.
void printEvaluation(std::FILE* out, const RecordedRun& run, const eval::RunEvaluation& result,
                     const EvalTiming& timing);

// <folder>/eval.json (keys sorted, two-space indent; everything but "timing" is the same for
// the same rawlog) and <folder>/coverage.csv (time,score,detected per tally improvement).
// Throws InputError naming the file when it cannot be written.
void writeEvaluationFiles(const std::filesystem::path& folder, const RecordedRun& run,
                          const eval::RunEvaluation& result, const EvalTiming& timing);

}  // namespace coinspect::app
