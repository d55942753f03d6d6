// Whole-mission real-time factor of `demo-paths` on the CARIC MBS data (config/caric-mbs.ini:
// 5 UAVs, 600 s budget). Counters: rtf (simulated s per wall s) and the wall seconds per stage.
#include <benchmark/benchmark.h>

#include <filesystem>

#include "coinspect/core/config.h"
#include "coinspect/sim/mission.h"
#include "coinspect/strategies/builtin.h"

namespace {

void BM_CaricMbsDemoPaths(benchmark::State& state) {
  const std::filesystem::path ini =
      std::filesystem::path(COINSPECT_SOURCE_DIR) / "config" / "caric-mbs.ini";
  if (!std::filesystem::exists(std::filesystem::path(COINSPECT_SHARED_DIR) / "data" / "caric-mbs" /
                               "mbs.stl")) {
    state.SkipWithError("CARIC MBS data not found beside the repository");
    return;
  }
  coinspect::agent::StrategyRegistry registry;
  coinspect::strategies::registerBuiltinStrategies(registry);
  for (auto _ : state) {
    auto config = coinspect::Config::fromFile(ini);
    coinspect::sim::Mission mission(config, registry);
    mission.run();
    const auto summary = mission.summary();
    state.counters["rtf"] = summary.realTimeFactor();
    state.counters["score"] = summary.score;
    state.counters["physics_s"] = summary.stages.physics;
    state.counters["lidar_s"] = summary.stages.lidar;
    state.counters["topology_s"] = summary.stages.topology;
    state.counters["scoring_s"] = summary.stages.scoring;
    state.counters["strategies_s"] = summary.stages.decisions;
  }
}
BENCHMARK(BM_CaricMbsDemoPaths)->Unit(benchmark::kSecond)->Iterations(1);

}  // namespace

BENCHMARK_MAIN();
