// Whole-mission real-time factor of `demo-paths` on the CARIC MBS data (config/caric-mbs.ini:
// 5 UAVs, 600 s budget), without and with recording the run as a rawlog (default [record]
// options: ground truth 20 Hz, LiDAR key frames, every capture, links, messages, events, tally),
// so that one run gives the recording overhead as a ratio. Counters: rtf (simulated s per wall
// s), the wall seconds per stage, and for the recorded run the rawlog's size and object count.
// Then the first 300 s of a `slei3d` feature mission on the generated `slei-c` (13 units: the
// station, 4 explorers with LiDARs, 8 inspectors; the Table-I settings of doc/strategies.md) on
// 1 and 2 threads (Mission::setThreads): rtf, stages, and `same` = 1 when the run's state digest
// equals the 1-thread run's (needs no external data).
#include <benchmark/benchmark.h>

#include <filesystem>

#include "coinspect/core/config.h"
#include "coinspect/core/version.h"
#include "coinspect/record/run_header.h"
#include "coinspect/sim/mission.h"
#include "coinspect/strategies/builtin.h"

namespace {

void BM_CaricMbsDemoPaths(benchmark::State& state) {
  const bool recorded = state.range(0) != 0;
  const std::filesystem::path ini =
      std::filesystem::path(COINSPECT_SOURCE_DIR) / "config" / "caric-mbs.ini";
  if (!std::filesystem::exists(std::filesystem::path(COINSPECT_SHARED_DIR) / "data" / "caric-mbs" /
                               "mbs.stl")) {
    state.SkipWithError("CARIC MBS data not found beside the repository");
    return;
  }
  const auto rawlog = std::filesystem::temp_directory_path() / "coinspect_bench_mission.rawlog";
  coinspect::agent::StrategyRegistry registry;
  coinspect::strategies::registerBuiltinStrategies(registry);
  for (auto _ : state) {
    auto config = coinspect::Config::fromFile(ini);
    coinspect::sim::Mission mission(config, registry);
    if (recorded) {
      coinspect::record::RunHeader header;
      header.coinspectVersion = coinspect::version();
      header.seed = mission.config().seed;
      header.scenarioHash = std::to_string(mission.scenario().contentHash());
      header.configIni = config.toText();
      mission.startRecording(rawlog, header);
    }
    mission.run();
    const auto summary = mission.summary();
    state.counters["rtf"] = summary.realTimeFactor();
    state.counters["score"] = summary.score;
    state.counters["physics_s"] = summary.stages.physics;
    state.counters["lidar_s"] = summary.stages.lidar;
    state.counters["topology_s"] = summary.stages.topology;
    state.counters["scoring_s"] = summary.stages.scoring;
    state.counters["strategies_s"] = summary.stages.decisions;
    if (recorded)
      state.counters["rawlog_MB"] = static_cast<double>(std::filesystem::file_size(rawlog)) / 1e6;
  }
  std::filesystem::remove(rawlog);
}
BENCHMARK(BM_CaricMbsDemoPaths)
    ->ArgName("recorded")
    ->Arg(0)
    ->Arg(1)
    ->Unit(benchmark::kSecond)
    ->Iterations(1)
    ->Repetitions(3);

void BM_SleiCThreads(benchmark::State& state) {
  const auto threads = static_cast<size_t>(state.range(0));
  static uint64_t oneThreadDigest = 0;
  coinspect::agent::StrategyRegistry registry;
  coinspect::strategies::registerBuiltinStrategies(registry);
  for (auto _ : state) {
    const auto config = coinspect::Config::fromText(
        "[mission]\nscenario = slei-c\nobjective = features\nlinks = range\nlink_range = 5\n"
        "gcs_speed = 1\nbudget = 300\n[strategy]\nname = slei3d\n[slei3d]\n"
        "handout_at_box_end = true\n",
        "bench-slei-c.ini");
    coinspect::sim::Mission mission(config, registry);
    mission.setThreads(threads);
    mission.run();
    const auto summary = mission.summary();
    if (threads == 1) oneThreadDigest = mission.stateDigest();
    state.counters["rtf"] = summary.realTimeFactor();
    state.counters["lidar_s"] = summary.stages.lidar;
    state.counters["strategies_s"] = summary.stages.decisions;
    state.counters["collected"] = static_cast<double>(summary.features.collected);
    state.counters["same"] = mission.stateDigest() == oneThreadDigest ? 1 : 0;
  }
}
BENCHMARK(BM_SleiCThreads)
    ->ArgName("threads")
    ->Arg(1)
    ->Arg(2)
    ->Unit(benchmark::kSecond)
    ->Iterations(1)
    ->Repetitions(2);

}  // namespace

BENCHMARK_MAIN();
