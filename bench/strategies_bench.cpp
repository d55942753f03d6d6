// Decision latency of every CARIC strategy: the CARIC MBS mission of its config/caric-mbs-*.ini
// (5 UAVs, reference start positions, `caric` scoring and links) flown for `budget` s of mission
// time, one run per strategy. Counters: the compute time of Strategy::decide per decision
// (p50, p95, max, in ms, over every unit's decisions), decisions made, the real-time factor and
// the score reached, so the strategies compare as ratios within one run of this program.
#include <benchmark/benchmark.h>

#include <filesystem>
#include <string>

#include "coinspect/core/config.h"
#include "coinspect/sim/mission.h"
#include "coinspect/strategies/builtin.h"

namespace {

struct Entry {
  const char* strategy;
  const char* config;  // in config/
};
constexpr Entry kStrategies[] = {{"caric-baseline", "caric-mbs-baseline.ini"},
                                 {"kios", "caric-mbs-kios.ini"},
                                 {"star", "caric-mbs-star.ini"},
                                 {"coinspect", "caric-mbs-coinspect.ini"}};
constexpr double kBudget = 300.0;  // s of mission time: past exploration into inspection

void runStrategy(benchmark::State& state, const Entry& entry) {
  const std::filesystem::path ini =
      std::filesystem::path(COINSPECT_SOURCE_DIR) / "config" / entry.config;
  if (!std::filesystem::exists(std::filesystem::path(COINSPECT_SHARED_DIR) / "data" / "caric-mbs" /
                               "mbs.stl")) {
    state.SkipWithError("CARIC MBS data not found beside the repository");
    return;
  }
  if (!std::filesystem::exists(ini)) {
    state.SkipWithError(("no config " + ini.filename().string()).c_str());
    return;
  }
  coinspect::agent::StrategyRegistry registry;
  coinspect::strategies::registerBuiltinStrategies(registry);
  for (auto _ : state) {
    auto config = coinspect::Config::fromFile(ini);
    config.set("mission", "budget", std::to_string(kBudget));
    coinspect::sim::Mission mission(config, registry);
    mission.run();
    const auto summary = mission.summary();
    const auto& times = summary.decisionTimes;
    state.counters["p50_ms"] = 1e3 * times.quantile(0.5);
    state.counters["p95_ms"] = 1e3 * times.quantile(0.95);
    state.counters["max_ms"] = 1e3 * times.max;
    state.counters["decisions"] = static_cast<double>(times.count);
    state.counters["rtf"] = summary.realTimeFactor();
    state.counters["score"] = summary.score;
    state.counters["collisions"] = static_cast<double>(summary.collisions);
  }
}

}  // namespace

int main(int argc, char** argv) {
  for (const Entry& entry : kStrategies)
    benchmark::RegisterBenchmark((std::string("BM_DecisionLatency/") + entry.strategy).c_str(),
                                 [&entry](benchmark::State& state) { runStrategy(state, entry); })
        ->Unit(benchmark::kSecond)
        ->Iterations(1);
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
