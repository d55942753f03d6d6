// Routing speed (libs/planning, routing_*.h): strategies call these inside decisions that must
// stay under 50 ms at p95, so the question is the time of one solve at the sizes they use.
//
// Instances: seeded random points in a 100 m cube; flying costs the distance plus twice the climb
// (asymmetric, like flight time with climbing), or the plain distance (symmetric); `uniform` is
// independent random costs, the hardest case for 2-opt/Or-opt. Each iteration solves from
// scratch; counters: the tour's cost and the local search's move evaluations.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <string>
#include <vector>

#include "coinspect/core/random.h"
#include "coinspect/planning/routing_exact.h"
#include "coinspect/planning/routing_genetic.h"
#include "coinspect/planning/routing_mtsp.h"
#include "coinspect/planning/routing_tsp.h"

namespace {

using namespace coinspect;
using namespace coinspect::planning;

enum Shape { kClimbing = 0, kEuclidean = 1, kUniform = 2 };

CostMatrix instance(Shape shape, int n, uint64_t seed) {
  Rng rng(seed);
  std::vector<Eigen::Vector3d> points;
  for (int i = 0; i < n; ++i) {
    const double x = rng.uniform(0, 100), y = rng.uniform(0, 100), z = rng.uniform(0, 100);
    points.emplace_back(x, y, z);
  }
  std::vector<double> costs(static_cast<size_t>(n) * n, 0.0);
  for (int a = 0; a < n; ++a) {
    for (int b = 0; b < n; ++b) {
      double& cost = costs[static_cast<size_t>(a) * n + b];
      if (shape == kUniform) {
        cost = rng.uniform(1.0, 100.0);
      } else {
        cost = (points[b] - points[a]).norm();
        if (shape == kClimbing) cost += 2.0 * std::max(0.0, points[b].z() - points[a].z());
      }
    }
  }
  return CostMatrix(n, std::move(costs));
}

const char* shapeName(int shape) {
  return shape == kClimbing ? "climbing" : (shape == kEuclidean ? "euclidean" : "uniform");
}

// args: nodes, shape, closed (1) or open (0), kicks (iterated local search rounds).
void BM_Tsp(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  const CostMatrix costs = instance(static_cast<Shape>(state.range(1)), n, 42);
  const TourProblem problem{state.range(2) ? TourKind::Closed : TourKind::Open, 0, -1};
  LocalSearchOptions options;
  options.kicks = static_cast<int>(state.range(3));
  RoutingStats stats;
  Tour tour;
  for (auto _ : state) {
    tour = solveTsp(costs, problem, options, &stats);
    benchmark::DoNotOptimize(tour.cost);
  }
  state.SetLabel(std::string(shapeName(static_cast<int>(state.range(1)))) +
                 (state.range(2) ? " closed" : " open") + " kicks " +
                 std::to_string(state.range(3)));
  state.counters["cost"] = tour.cost;
  state.counters["construction"] = stats.constructionCost;
  state.counters["evaluations"] = static_cast<double>(stats.evaluations);
}
BENCHMARK(BM_Tsp)
    ->Args({50, kClimbing, 1, 0})
    ->Args({100, kClimbing, 1, 0})
    ->Args({100, kClimbing, 0, 0})
    ->Args({100, kEuclidean, 1, 0})
    ->Args({100, kUniform, 1, 0})
    ->Args({200, kClimbing, 1, 0})
    ->Args({100, kClimbing, 1, 20})
    ->Args({100, kUniform, 1, 20})
    ->Unit(benchmark::kMillisecond);

// args: nodes (vehicle starts included), vehicles, objective (0 min-sum, 1 min-max), depot (1).
void BM_Mtsp(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  const int m = static_cast<int>(state.range(1));
  const CostMatrix costs = instance(kClimbing, n, 43);
  MtspProblem problem;
  for (int v = 0; v < m; ++v)
    problem.starts.push_back(v);
  problem.objective = state.range(2) ? MtspObjective::MinMax : MtspObjective::MinSum;
  problem.depot = state.range(3) ? m : -1;
  RoutingStats stats;
  MtspSolution solution;
  for (auto _ : state) {
    solution = solveMtsp(costs, problem, {}, &stats);
    benchmark::DoNotOptimize(solution.totalCost);
  }
  state.SetLabel(std::string(state.range(2) ? "min-max" : "min-sum") +
                 (state.range(3) ? " depot" : " open"));
  state.counters["total"] = solution.totalCost;
  state.counters["makespan"] = solution.makespan;
  state.counters["evaluations"] = static_cast<double>(stats.evaluations);
}
BENCHMARK(BM_Mtsp)
    ->Args({100, 5, 0, 0})
    ->Args({200, 5, 0, 0})
    ->Args({200, 5, 1, 0})
    ->Args({200, 5, 1, 1})
    ->Unit(benchmark::kMillisecond);

// args: nodes, vehicles; min-max, open routes, default GA options (24 x 40).
void BM_Genetic(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  const int m = static_cast<int>(state.range(1));
  const CostMatrix costs = instance(kClimbing, n, 44);
  MtspProblem problem;
  for (int v = 0; v < m; ++v)
    problem.starts.push_back(v);
  problem.objective = MtspObjective::MinMax;
  GeneticResult result;
  for (auto _ : state) {
    result = geneticMtsp(costs, problem);
    benchmark::DoNotOptimize(result.best.makespan);
  }
  const MtspSolution heuristic = solveMtsp(costs, problem);
  state.counters["makespan"] = result.best.makespan;
  state.counters["initial_makespan"] = result.initialBest.makespan;
  state.counters["heuristic_makespan"] = heuristic.makespan;
  state.counters["evaluations"] = static_cast<double>(result.evaluations);
}
BENCHMARK(BM_Genetic)->Args({30, 1})->Args({50, 3})->Unit(benchmark::kMillisecond);

void BM_HeldKarp(benchmark::State& state) {
  const CostMatrix costs = instance(kClimbing, static_cast<int>(state.range(0)), 45);
  for (auto _ : state)
    benchmark::DoNotOptimize(heldKarp(costs, {}).cost);
}
BENCHMARK(BM_HeldKarp)->Arg(10)->Arg(12)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
