// `coinspect run <config.ini>`: flies a mission (doc/config.md, "Missions (coinspect run)") and
// prints its summary; with --out, also records run.rawlog and writes summary.txt, events.csv,
// score.csv, report.json and one <unit>.tum trajectory per unit there.
#include <algorithm>
#include <cstdio>
#include <memory>
#include <optional>

#include "coinspect/core/config.h"
#include "coinspect/core/error.h"
#include "coinspect/sim/mission.h"
#include "coinspect/strategies/builtin.h"
#include "commands.h"
#include "option_checks.h"
#include "progress.h"
#include "run_outputs.h"

namespace coinspect::app {

namespace {

struct RunOptions {
  std::string config;
  std::vector<std::string> overrides;
  std::optional<uint64_t> seed;
  std::string out;
  bool quiet = false;
  int threads = 0;  // 0: one per hardware thread
};

// Flies the mission in steps of 1 s of simulated time, drawing the progress line (stdout, like
// the rest of the run's output) after each; it also stops at every 10 % of the total, so that
// the plain lines of a pipe fall on those instants. Until take-off the total is the budget; then
// it is the mission's end, take-off time + budget.
void flyWithProgress(sim::Mission& mission) {
  const double budget = mission.summary().budget;
  double total = budget;
  ProgressLine progress(stdout, "progress", total);
  bool totalKnown = false;
  double nextSecond = 1.0;
  int nextTenth = 1;
  while (!mission.finished()) {
    // Past the last tenth only the seconds remain: a budget shorter than the time to take-off
    // puts every tenth before the present, and stopping there again would never step.
    const double tenthAt = nextTenth <= 10 ? total * nextTenth / 10.0 : nextSecond;
    mission.runUntil(std::min(nextSecond, tenthAt));
    const auto summary = mission.summary();
    if (!totalKnown && summary.started) {
      total = summary.startTime + budget;
      progress.setTotal(total);
      totalKnown = true;
    }
    // runUntil stops at the first tick at or after its time.
    while (nextSecond <= summary.simTime + 1e-9)
      nextSecond += 1.0;
    while (nextTenth <= 10 && total * nextTenth / 10.0 <= summary.simTime + 1e-9)
      ++nextTenth;
    progress.update(summary.simTime, summary.score, summary.detected, summary.totalPoints);
  }
  progress.finish();
}

void runMission(const RunOptions& options) {
  auto ini = Config::fromFile(options.config);
  for (const auto& assignment : options.overrides)
    ini.applyOverride(assignment);
  agent::StrategyRegistry registry;
  strategies::registerBuiltinStrategies(registry);
  sim::Mission mission(ini, registry, options.seed);
  ini.requireAllKeysUsed();
  mission.setThreads(static_cast<size_t>(options.threads));
  std::printf("flying     %s: %zu units, %zu interest points, budget %.0f s\n",
              mission.scenario().name.c_str(), mission.scenario().fleet.size(),
              mission.scenario().interestPoints.size(), mission.summary().budget);
  std::fflush(stdout);
  std::unique_ptr<RunOutputs> outputs;
  if (!options.out.empty()) outputs = std::make_unique<RunOutputs>(mission, options.out, ini);
  if (options.quiet)
    mission.run();
  else
    flyWithProgress(mission);
  const std::string text = sim::formatSummary(mission.summary());
  std::fputs(text.c_str(), stdout);
  if (!options.out.empty()) {
    outputs->finish(mission, ini, options.config, text);
    std::printf("outputs    %s\n", options.out.c_str());
    if (const auto rawlog = mission.recordingPath())
      std::printf("rawlog     %s\n", rawlog->string().c_str());
  }
  // A failed recording stopped the mission early; the other outputs are written, the run fails.
  if (const auto& error = mission.recordingError())
    throw InputError(*error, "", "recording failed, the mission was stopped there");
}

}  // namespace

void addRunCommand(CLI::App& root) {
  auto options = std::make_shared<RunOptions>();
  auto* run = root.add_subcommand("run", "Fly a mission from a config file and print a summary");
  run->add_option("config", options->config, "mission INI file (see config/)")->required();
  run->add_option("--set", options->overrides, "override a key: section.key=value (repeatable)");
  run->add_option("--seed", options->seed, "run seed (replaces [mission] seed)")
      ->check(seedNumber());
  run->add_option("--out", options->out,
                  "folder for run.rawlog, summary.txt, events.csv, score.csv, report.json, "
                  "<unit>.tum")
      ->check(nonEmptyPath());
  run->add_flag("--quiet", options->quiet, "no progress line while the mission flies");
  run->add_option("--threads", options->threads,
                  "threads for the units' decisions and LiDAR sweeps (0, the default: one per "
                  "hardware thread); the results do not depend on it")
      ->check(CLI::Range(0, 256));
  run->callback([options] { runMission(*options); });
}

}  // namespace coinspect::app
