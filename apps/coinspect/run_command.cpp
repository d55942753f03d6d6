// `coinspect run <config.ini>`: flies a mission (doc/config.md, "Missions (coinspect run)") and
// prints its summary; with --out, also writes summary.txt, events.csv, score.csv, report.json and
// one <unit>.tum trajectory per unit there.
#include <cstdio>
#include <memory>
#include <optional>

#include "coinspect/core/config.h"
#include "coinspect/core/error.h"
#include "coinspect/sim/mission.h"
#include "coinspect/strategies/builtin.h"
#include "commands.h"
#include "run_outputs.h"

namespace coinspect::app {

namespace {

struct RunOptions {
  std::string config;
  std::vector<std::string> overrides;
  std::optional<uint64_t> seed;
  std::string out;
};

void runMission(const RunOptions& options) {
  auto ini = Config::fromFile(options.config);
  for (const auto& assignment : options.overrides)
    ini.applyOverride(assignment);
  agent::StrategyRegistry registry;
  strategies::registerBuiltinStrategies(registry);
  sim::Mission mission(ini, registry, options.seed);
  ini.requireAllKeysUsed();
  std::printf("flying     %s: %zu units, %zu interest points, budget %.0f s\n",
              mission.scenario().name.c_str(), mission.scenario().fleet.size(),
              mission.scenario().interestPoints.size(), mission.summary().budget);
  std::fflush(stdout);
  std::unique_ptr<RunOutputs> outputs;
  if (!options.out.empty()) outputs = std::make_unique<RunOutputs>(mission, options.out);
  mission.run();
  const std::string text = sim::formatSummary(mission.summary());
  std::fputs(text.c_str(), stdout);
  if (!options.out.empty()) {
    outputs->finish(mission, ini, options.config, text);
    std::printf("outputs    %s\n", options.out.c_str());
  }
}

}  // namespace

void addRunCommand(CLI::App& root) {
  auto options = std::make_shared<RunOptions>();
  auto* run = root.add_subcommand("run", "Fly a mission from a config file and print a summary");
  run->add_option("config", options->config, "mission INI file (see config/)")->required();
  run->add_option("--set", options->overrides, "override a key: section.key=value (repeatable)");
  run->add_option("--seed", options->seed, "run seed (replaces [mission] seed)");
  run->add_option("--out", options->out,
                  "folder for summary.txt, events.csv, score.csv, report.json, <unit>.tum");
  run->callback([options] { runMission(*options); });
}

}  // namespace coinspect::app
