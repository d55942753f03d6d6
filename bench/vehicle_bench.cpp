// Multirotor dynamics: simulated seconds per wall second of one explorer flying a waypoint pattern
// (60 s, commands at 20 Hz, advanced in 2.5 ms steps as the sim does), integrated by CVODE at
// several tolerances and by the fixed-step RK4 reference at 1 kHz.
//
// Accuracy: each configuration's trajectory is compared, at every 2.5 ms, with RK4 at 0.05 ms
// (the "truth" of the same model); counters max_error_m and final_error_m. This is the
// convergence test that chose IntegratorOptions' default tolerances.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <vector>

#include "coinspect/vehicle/airframe.h"
#include "coinspect/vehicle/multirotor.h"

namespace {

using namespace coinspect::vehicle;

constexpr double kStep = 0.0025;
constexpr double kFlightSeconds = 60.0;

const Airframe& explorer() {
  // The shipped airframes, found relative to this source file.
  static const Airframe airframe =
      loadAirframes(std::filesystem::path(__FILE__).parent_path().parent_path() / "share" /
                    "coinspect" / "airframes.ini")
          .at("explorer");
  return airframe;
}

// Flies the pattern; returns the positions at every step.
std::vector<Vec3> flyPattern(const IntegratorOptions& options, long* evaluations = nullptr) {
  const Vec3 waypoints[] = {{20, 0, 10}, {20, 20, 15}, {0, 20, 5}, {0, 0, 10}, {10, 10, 20}};
  Multirotor vehicle(explorer(), Vec3(0, 0, 0.1), 0.0, 0.0, options);
  const int steps = static_cast<int>(kFlightSeconds / kStep + 0.5);
  std::vector<Vec3> trace;
  trace.reserve(steps);
  for (int i = 0; i < steps; ++i) {
    const int leg = i / 2400;  // a new waypoint every 6 s
    if (i % 20 == 0) {
      vehicle.command(positionSetpoint(waypoints[leg % 5], 0.7 * leg), vehicle.state().time);
    }
    vehicle.advance(kStep);
    trace.push_back(vehicle.state().position);
  }
  if (evaluations) *evaluations = vehicle.integratorEvaluations();
  return trace;
}

const std::vector<Vec3>& truth() {
  static const std::vector<Vec3> trace = [] {
    IntegratorOptions fine;
    fine.method = Integrator::Rk4;
    fine.rk4Step = 5e-5;
    return flyPattern(fine);
  }();
  return trace;
}

void run(benchmark::State& state, const IntegratorOptions& options) {
  long evaluations = 0;
  const std::vector<Vec3> trace = flyPattern(options, &evaluations);
  double maxError = 0.0;
  for (size_t i = 0; i < trace.size(); ++i) {
    maxError = std::max(maxError, (trace[i] - truth()[i]).norm());
  }
  for (auto _ : state)
    benchmark::DoNotOptimize(flyPattern(options).back());
  state.counters["sim_s_per_wall_s"] = benchmark::Counter(
      kFlightSeconds * static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
  state.counters["rhs_per_sim_s"] = static_cast<double>(evaluations) / kFlightSeconds;
  state.counters["max_error_m"] = maxError;
  state.counters["final_error_m"] = (trace.back() - truth().back()).norm();
}

void BM_Cvode(benchmark::State& state) {
  IntegratorOptions options;
  options.relativeTolerance = std::pow(10.0, -static_cast<double>(state.range(0)));
  options.absoluteTolerance = options.relativeTolerance * 1e-2;
  run(state, options);
}
BENCHMARK(BM_Cvode)
    ->ArgName("minus_log10_rtol")
    ->Arg(4)
    ->Arg(5)
    ->Arg(6)
    ->Arg(8)
    ->Unit(benchmark::kMillisecond);

void BM_CvodeDefaults(benchmark::State& state) {
  run(state, IntegratorOptions{});
}
BENCHMARK(BM_CvodeDefaults)->Unit(benchmark::kMillisecond);

// Outputs only at the control ticks (advance(0.05), two waypoints 20 m apart every 6 s): the cost
// of the segments themselves (CVodeReInit and steps), without the 2.5 ms outputs.
void BM_TickOutputs(benchmark::State& state) {
  IntegratorOptions options;
  if (state.range(0) == 1) options.method = Integrator::Rk4;
  for (auto _ : state) {
    Multirotor vehicle(explorer(), Vec3(0, 0, 0.1), 0.0, 0.0, options);
    for (int k = 0; k < static_cast<int>(kFlightSeconds / 0.05); ++k) {
      const Vec3 target(20.0 * ((k / 120) % 2), 0, 10);
      vehicle.command(positionSetpoint(target, 0.0), vehicle.state().time);
      vehicle.advance(0.05);
    }
    benchmark::DoNotOptimize(vehicle.state().position);
  }
  state.counters["sim_s_per_wall_s"] = benchmark::Counter(
      kFlightSeconds * static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_TickOutputs)->ArgName("rk4")->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

void BM_Rk4(benchmark::State& state) {
  IntegratorOptions options;
  options.method = Integrator::Rk4;
  options.rk4Step = 1.0 / static_cast<double>(state.range(0));
  run(state, options);
}
BENCHMARK(BM_Rk4)->ArgName("hz")->Arg(400)->Arg(1000)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
