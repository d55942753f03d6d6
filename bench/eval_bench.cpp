// Speed of `coinspect eval`'s evaluator: simulated seconds of a recorded run evaluated per wall
// second (goal: >= 500x real time on the MBS mission). The fixture flies config/mbs.ini (the
// generated MBS, 5 UAVs, demo-paths) for kBudget simulated seconds once, recording it with the
// default [record] options, then each iteration evaluates the rawlog from the start. Counters:
// rtf (simulated s per CPU s of the evaluating thread, robust on a shared machine), captures,
// objects, rawlog_MiB; `equal` must be 1.
#include <benchmark/benchmark.h>

#include <unistd.h>
#include <cstdio>
#include <filesystem>
#include <string>

#include "coinspect/core/config.h"
#include "coinspect/eval/evaluate_run.h"
#include "coinspect/sim/mission.h"
#include "coinspect/strategies/builtin.h"
#include "coinspect/world/ray_caster.h"

namespace {

constexpr const char* kBudget = "300";  // simulated s of the recorded mission

struct RecordedMbs {
  std::filesystem::path rawlog;
  coinspect::world::Scenario scenario;
  coinspect::sim::MissionConfig config;
  double liveScore = 0.0;
  double liveRealTimeFactor = 0.0;

  RecordedMbs() {
    rawlog = std::filesystem::temp_directory_path() /
             ("coinspect-eval-bench-" + std::to_string(::getpid()) + ".rawlog");
    auto ini = coinspect::Config::fromFile(std::filesystem::path(COINSPECT_SOURCE_DIR) / "config" /
                                           "mbs.ini");
    ini.applyOverride(std::string("mission.budget=") + kBudget);
    coinspect::agent::StrategyRegistry registry;
    coinspect::strategies::registerBuiltinStrategies(registry);
    coinspect::sim::Mission mission(ini, registry);
    mission.startRecording(
        rawlog, coinspect::record::RunHeader{"bench", mission.config().seed, "0", ini.toText()});
    mission.run();
    scenario = mission.scenario();
    config = mission.config();
    liveScore = mission.gcsScore();
    liveRealTimeFactor = mission.summary().realTimeFactor();
  }
  ~RecordedMbs() { std::filesystem::remove(rawlog); }
};

const RecordedMbs& recordedMbs() {
  static const RecordedMbs run;
  return run;
}

void BM_EvaluateMbsDemoPaths(benchmark::State& state) {
  const RecordedMbs& run = recordedMbs();
  coinspect::eval::EvaluationParams params;
  params.scoring = run.config.scoring;
  params.physicsStep = run.config.physicsStep;
  params.source = run.rawlog.string();
  double simSeconds = 0.0;
  coinspect::eval::RunEvaluation result;
  for (auto _ : state) {
    coinspect::record::RawlogReader reader(run.rawlog);
    result = coinspect::eval::evaluateRun(reader, run.scenario, params);
    simSeconds += result.endTime;
  }
  state.counters["rtf"] = benchmark::Counter(simSeconds, benchmark::Counter::kIsRate);
  state.counters["sim_s"] = result.endTime;
  state.counters["captures"] = static_cast<double>(result.capturesCompared);
  state.counters["objects"] = static_cast<double>(result.read.objects);
  state.counters["rawlog_MiB"] =
      static_cast<double>(std::filesystem::file_size(run.rawlog)) / (1024.0 * 1024.0);
  state.counters["equal"] = result.equal() && result.score == run.liveScore ? 1.0 : 0.0;
  state.counters["live_rtf"] = run.liveRealTimeFactor;
}
BENCHMARK(BM_EvaluateMbsDemoPaths)->Unit(benchmark::kMillisecond)->MinTime(2.0);

// The evaluator's fixed cost, paid once per rawlog whatever its length: the Embree scene of the
// scenario's meshes, built as the mission builds it.
void BM_EvaluatorSetupMbs(benchmark::State& state) {
  const RecordedMbs& run = recordedMbs();
  for (auto _ : state) {
    coinspect::world::RayCaster caster(run.scenario.meshes, run.scenario.groundZ);
    benchmark::DoNotOptimize(caster);
  }
}
BENCHMARK(BM_EvaluatorSetupMbs)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
