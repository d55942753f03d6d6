// `coinspect eval RAWLOG [--scenario SOURCE] [--out DIR]`: scores a recorded run again from its
// capture states and the scenario, compares the result with the recorded ground-station tally and
// reports what the rawlog allows (doc/evaluation.md). Exit status: 0 clean and equal, 1 damaged
// rawlog (results up to the damage are printed), 3 re-scored differs from recorded.
#include <chrono>
#include <cstdio>
#include <memory>

#include "coinspect/eval/evaluate_run.h"
#include "coinspect/record/rawlog_reader.h"
#include "commands.h"
#include "eval_report.h"
#include "option_checks.h"
#include "progress.h"
#include "recorded_run.h"

namespace coinspect::app {

namespace {

struct EvalOptions {
  std::string rawlog;
  std::string scenario;
  std::string out;
};

// Exit statuses besides 0 (doc/evaluation.md, "Exit status").
constexpr int kStatusDamaged = 1;
constexpr int kStatusDifferent = 3;

void evaluateRecordedRun(const EvalOptions& options) {
  const RecordedRun run = openRecordedRun(options.rawlog, options.scenario);
  record::RawlogReader reader(run.rawlog);
  reader.setLatestTime(run.latestTime());
  eval::EvaluationParams params;
  params.scoring = run.mission.scoring;
  params.physicsStep = run.mission.physicsStep;
  params.source = run.rawlog.string();

  const double budget = run.mission.budget.value_or(run.scenario.missionBudget);
  ProgressLine progress(stderr, "eval", budget);
  const auto start = std::chrono::steady_clock::now();
  const auto result =
      eval::evaluateRun(reader, run.scenario, params, [&](const eval::EvaluationProgress& p) {
        if (p.missionStart >= 0.0) progress.setTotal(p.missionStart + budget);
        progress.update(p.time, p.score, p.detected, p.pointCount);
      });
  progress.finish();
  EvalTiming timing;
  timing.wallTime = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  timing.simTime = result.endTime;

  printEvaluation(stdout, run, result, timing);
  if (!options.out.empty()) {
    writeEvaluationFiles(options.out, run, result, timing);
    std::printf("outputs    %s\n", options.out.c_str());
  }
  std::fflush(stdout);
  if (!result.read.clean) {
    std::fprintf(stderr, "coinspect: rawlog damaged: %s\n", result.read.message.c_str());
    throw CommandStatus{kStatusDamaged};
  }
  if (!result.equal()) throw CommandStatus{kStatusDifferent};
}

}  // namespace

void addEvalCommand(CLI::App& root) {
  auto options = std::make_shared<EvalOptions>();
  auto* eval = root.add_subcommand(
      "eval", "Score a recorded run again and compare with the recorded score (doc/evaluation.md)");
  eval->add_option("rawlog", options->rawlog, "run.rawlog written by coinspect run --out")
      ->required();
  eval->add_option("--scenario", options->scenario,
                   "scenario SOURCE (generator, scenario.ini, CARIC folder) when the recorded one "
                   "cannot be found; its content hash must match the recorded one")
      ->check(nonEmptyPath());
  eval->add_option("--out", options->out, "folder for eval.json and coverage.csv")
      ->check(nonEmptyPath());
  eval->footer(
      "Exit status: 0 when the rawlog is clean and the re-scored tally equals the recorded one, "
      "1 when the rawlog is damaged (results up to the damage are printed), 2 for bad input, 3 "
      "when the re-scored tally differs from the recorded one.");
  eval->callback([options] { evaluateRecordedRun(*options); });
}

}  // namespace coinspect::app
