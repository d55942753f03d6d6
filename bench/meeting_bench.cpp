// SLEI3D decision speed (libs/planning, meeting_decision.h and slei_meeting_order.h): an
// explorer's SOEI decision (which inspectors to meet, where, with which features) and the
// station's meeting order, at the sizes of the paper's scenes: 2 to 6 inspectors per explorer
// (scene D and the 75-robot run have 5-6), 30 pending features, 1 to 8 planned hover poses per
// inspector; 4 to 12 station meetings (one per explorer). Goal: SOEI p95 < 100 ms.
//
// Instances: a 40 x 40 x 12 m grid at 0.5 m with random pillars (free elsewhere), inspectors'
// poses and features at random free places, seeded; each iteration decides one fresh instance of
// the series (seed = iteration), so the counters give p50/p95 over instances.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <vector>

#include "coinspect/core/random.h"
#include "coinspect/mapping/voxel_grid.h"
#include "coinspect/planning/meeting_decision.h"
#include "coinspect/planning/slei_meeting_order.h"

namespace {

using namespace coinspect;
using namespace coinspect::planning;

mapping::VoxelGrid pillars(uint64_t seed) {
  mapping::VoxelGrid grid(Vec3(0, 0, 0), 0.5, mapping::Index3(80, 80, 24),
                          mapping::CellState::Free);
  Rng rng(seed);
  for (int p = 0; p < 12; ++p) {
    const int cx = static_cast<int>(rng.below(70)) + 5, cy = static_cast<int>(rng.below(70)) + 5;
    for (int z = 0; z < 20; ++z)
      for (int y = cy - 2; y <= cy + 2; ++y)
        for (int x = cx - 2; x <= cx + 2; ++x)
          grid.set({x, y, z}, mapping::CellState::Occupied);
  }
  grid.computeClearance(6.0, true);
  return grid;
}

Vec3 freePoint(const mapping::VoxelGrid& grid, Rng& rng) {
  for (;;) {
    const Vec3 p(rng.uniform(4, 36), rng.uniform(4, 36), rng.uniform(2, 9));
    if (grid.clearance(grid.cellOf(p)) >= 1.5) return p;
  }
}

double quantile(std::vector<double> samples, double q) {
  std::sort(samples.begin(), samples.end());
  return samples[std::min(samples.size() - 1, static_cast<size_t>(q * samples.size()))];
}

// Times one call of `solve` into `times` (seconds).
template <class Solve>
void timed(std::vector<double>& times, Solve solve) {
  const auto start = std::chrono::steady_clock::now();
  benchmark::DoNotOptimize(solve());
  times.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
}

void reportQuantiles(benchmark::State& state, const std::vector<double>& times) {
  state.counters["p50_ms"] = 1e3 * quantile(times, 0.5);
  state.counters["p95_ms"] = 1e3 * quantile(times, 0.95);
}

// args: inspectors, poses per inspector.
void BM_SoeiDecision(benchmark::State& state) {
  const int inspectors = static_cast<int>(state.range(0));
  const int poses = static_cast<int>(state.range(1));
  const auto grid = pillars(7);
  const auto space = voxelGridMeetingSpace(grid, 1.5);
  const MeetingBox box{Vec3(0, 0, 0), Vec3(40, 40, 12)};
  std::vector<double> times;
  uint64_t seed = 0;
  for (auto _ : state) {
    state.PauseTiming();
    Rng rng(++seed);
    MeetingProblem problem;
    problem.explorer = {freePoint(grid, rng), 100.0};
    for (int i = 0; i < inspectors; ++i) {
      InspectorPlan plan;
      plan.id = i;
      double t = 100.0 + rng.uniform(0, 20);
      for (int p = 0; p < poses; ++p) {
        plan.poses.push_back({freePoint(grid, rng), t, t + 5.0});
        t += 5.0 + rng.uniform(5, 15);
      }
      plan.poses.back().end = kOpenWindowEnd;
      problem.inspectors.push_back(plan);
    }
    for (int f = 0; f < 30; ++f) {
      const Vec3 p = freePoint(grid, rng);
      problem.features.push_back({f, p, p});
    }
    MeetingOptions options;
    options.seed = seed;
    state.ResumeTiming();
    timed(times, [&] { return decideMeetings(problem, box, space, options); });
  }
  reportQuantiles(state, times);
}
BENCHMARK(BM_SoeiDecision)
    ->ArgsProduct({{2, 4, 6}, {1, 4, 8}})
    ->Iterations(40)
    ->Unit(benchmark::kMillisecond);

// args: meetings (exact up to 12, heuristic beyond).
void BM_StationMeetingOrder(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  std::vector<double> times;
  uint64_t seed = 0;
  for (auto _ : state) {
    state.PauseTiming();
    Rng rng(++seed);
    MeetingOrderProblem problem;
    problem.start = Vec3(0, 0, 0);
    problem.startTime = 0.0;
    for (int i = 0; i < n; ++i) {
      GcsMeeting m;
      m.id = i;
      m.place = Vec3(rng.uniform(-60, 60), rng.uniform(-80, 80), 0.0);
      m.earliest = rng.uniform(60, 600);
      m.latest = m.earliest + 60.0;
      m.service = 10.0;
      problem.meetings.push_back(m);
    }
    state.ResumeTiming();
    timed(times, [&] { return planMeetingOrder(problem); });
  }
  reportQuantiles(state, times);
}
BENCHMARK(BM_StationMeetingOrder)
    ->Arg(4)
    ->Arg(8)
    ->Arg(12)
    ->Arg(20)
    ->Iterations(40)
    ->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
