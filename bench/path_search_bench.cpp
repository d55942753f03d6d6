// Path search on an MBS-sized grid: the generated `mbs` scenario (three towers under the sky
// deck, the lotus museum) voxelised at 1 m into 160 x 90 x 60 cells (its surface cells and the
// ground layer occupied, the rest free, as a LiDAR map would know them), clearance capped at 5 m.
//
// Queries (`query` 0-4) cross the scene: under and around the deck, between the towers, from one
// end to the other. Rows: the clearance field, A* and Theta* with heuristic weights 1 (least
// cost), 1.2 and 1.5 (`weight_x10`), and the smoothing and time parametrisation of the A* path;
// counters: expansions, path cost (m), straight-line distance and vertices. Search options: 1 m
// required clearance, soft clearance 3 m (weight 1), unknown cells blocked.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>

#include "coinspect/planning/path_search.h"
#include "coinspect/planning/path_smoothing.h"
#include "coinspect/planning/trajectory.h"
#include "coinspect/world/generators.h"

namespace {

using namespace coinspect;
using planning::Index3;
using planning::Vec3;

// Marks every cell a triangle passes through, by sampling it at a third of a cell.
void rasterise(const world::TriangleMesh& mesh, mapping::VoxelGrid& grid) {
  const double spacing = grid.resolution() / 3.0;
  for (const auto& triangle : mesh.triangles) {
    const Vec3 a = mesh.vertex(triangle[0]), b = mesh.vertex(triangle[1]),
               c = mesh.vertex(triangle[2]);
    const double longest = std::max({(b - a).norm(), (c - a).norm(), (c - b).norm()});
    const int n = std::max(1, static_cast<int>(std::ceil(longest / spacing)));
    for (int i = 0; i <= n; ++i)
      for (int j = 0; i + j <= n; ++j) {
        const Index3 cell = grid.cellOf(a + (b - a) * (double(i) / n) + (c - a) * (double(j) / n));
        if (grid.contains(cell)) grid.set(cell, mapping::CellState::Occupied);
      }
  }
}

const mapping::VoxelGrid& mbsGrid() {
  static const mapping::VoxelGrid grid = [] {
    const world::Scenario scenario = world::generateScenario("mbs", 1);
    // The scene spans (-41.6, -35.6, 0) to (96.2, 26.2, 59.4): about 10 m of margin around it.
    mapping::VoxelGrid g(Vec3(-52.0, -46.0, 0.0), 1.0, Index3(160, 90, 60),
                         mapping::CellState::Free);
    for (const auto& mesh : scenario.meshes)
      rasterise(mesh, g);
    for (int y = 0; y < 90; ++y)  // the ground, as the LiDAR sees it
      for (int x = 0; x < 160; ++x)
        g.set(Index3(x, y, 0), mapping::CellState::Occupied);
    g.computeClearance(5.0, true);
    return g;
  }();
  return grid;
}

struct Query {
  Vec3 start, goal;
};
const Query kQueries[] = {
    {{-45.0, -40.0, 10.0}, {103.0, 38.0, 30.0}},  // corner to corner, low to mid height
    {{103.0, -40.0, 5.0}, {-45.0, 38.0, 52.0}},   // corner to corner, up to the deck's height
    {{40.0, 35.0, 54.0}, {40.0, -42.0, 54.0}},    // straight through the sky deck's level
    {{11.0, 35.0, 30.0}, {70.0, -42.0, 30.0}},    // between the towers at mid height
    {{-48.0, 0.0, 3.0}, {105.0, -20.0, 57.0}},    // end to end, ground to deck
};

planning::PathSearchOptions searchOptions() {
  planning::PathSearchOptions options;
  options.clearance = 1.0;
  options.softClearance = 3.0;
  options.softWeight = 1.0;
  return options;
}

// The whole field with a cap of `range(0)` m (the robots' planning grids: 6 m at 0.5 to 1 m, so
// 7 to 13 cells): the y and z passes cost in proportion to the cap's cells.
void BM_ClearanceField(benchmark::State& state) {
  mapping::VoxelGrid grid = mbsGrid();
  const double cap = static_cast<double>(state.range(0));
  for (auto _ : state)
    grid.computeClearance(cap, true);
  state.counters["cells"] = static_cast<double>(grid.cellCount());
}
BENCHMARK(BM_ClearanceField)->Arg(5)->Arg(12)->Arg(30)->Unit(benchmark::kMillisecond);

// The update after a change inside a cube of `edge` cells (a scan's or a merge's footprint) in
// the middle of the scene: the cube's surface toggles between occupied and free each iteration,
// and VoxelGrid::updateClearance recomputes the field within the cap of it only (the robots'
// planning grids are rebuilt this way, runtime::RobotMap).
void BM_ClearanceUpdate(benchmark::State& state) {
  mapping::VoxelGrid grid = mbsGrid();
  const int edge = static_cast<int>(state.range(0));
  const Index3 low(80 - edge / 2, 45 - edge / 2, 30 - edge / 2);
  const Index3 high = low + Index3::Constant(edge - 1);
  bool occupied = false;
  for (auto _ : state) {
    occupied = !occupied;
    for (int z = low.z(); z <= high.z(); ++z)
      for (int y = low.y(); y <= high.y(); ++y)
        for (int x = low.x(); x <= high.x(); ++x) {
          const Index3 cell(x, y, z);
          const bool surface =
              (cell.array() == low.array()).any() || (cell.array() == high.array()).any();
          if (surface)
            grid.set(cell, occupied ? mapping::CellState::Occupied : mapping::CellState::Free);
        }
    grid.updateClearance(low, high);
  }
  state.counters["cells"] = static_cast<double>(grid.cellCount());
}
BENCHMARK(BM_ClearanceUpdate)->Arg(2)->Arg(10)->Arg(20)->Arg(40)->Unit(benchmark::kMillisecond);

void search(benchmark::State& state, bool anyAngle) {
  const mapping::VoxelGrid& grid = mbsGrid();
  const Query& query = kQueries[state.range(0)];
  auto options = searchOptions();
  options.heuristicWeight = state.range(1) / 10.0;
  planning::PathSearcher searcher;
  planning::PathResult result;
  for (auto _ : state) {
    result = anyAngle ? searcher.thetaStar(grid, query.start, query.goal, options)
                      : searcher.aStar(grid, query.start, query.goal, options);
    benchmark::DoNotOptimize(result.cost);
  }
  if (result.status != planning::PathStatus::Found)
    state.SkipWithError(planning::toString(result.status));
  state.counters["expansions"] = static_cast<double>(result.expansions);
  state.counters["cost_m"] = result.cost;
  state.counters["straight_m"] = (query.goal - query.start).norm();
  state.counters["vertices"] = static_cast<double>(result.points.size());
}
void BM_AStar(benchmark::State& state) {
  search(state, false);
}
void BM_ThetaStar(benchmark::State& state) {
  search(state, true);
}
BENCHMARK(BM_AStar)
    ->ArgsProduct({{0, 1, 2, 3, 4}, {10, 12, 15}})
    ->ArgNames({"query", "weight_x10"})
    ->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ThetaStar)
    ->ArgsProduct({{0, 1, 2, 3, 4}, {10, 12, 15}})
    ->ArgNames({"query", "weight_x10"})
    ->Unit(benchmark::kMillisecond);

// A goal walled off in a pocket (a hollow 9-cell cube of occupied cells at mid height between
// the towers; its free middle keeps the clearance), searched from each query's start with the
// strategies' budget (150 k expansions) and Theta* w = 1.5, as runtime::Flight plans: with
// partial paths (`partial_path` 1) the search spends the whole budget before it gives up;
// without (0) two floods prove the goal unreachable. Rows with `pocket` 0 are the queries' own
// reachable goals, without partial paths: what the goal-side flood adds to a found path.
const mapping::VoxelGrid& pocketGrid() {
  static const mapping::VoxelGrid grid = [] {
    mapping::VoxelGrid g = mbsGrid();
    const Index3 low = g.cellOf(Vec3(36.0, -10.0, 25.0));
    for (int z = 0; z < 9; ++z)
      for (int y = 0; y < 9; ++y)
        for (int x = 0; x < 9; ++x) {
          const bool wall = x == 0 || y == 0 || z == 0 || x == 8 || y == 8 || z == 8;
          g.set(low + Index3(x, y, z),
                wall ? mapping::CellState::Occupied : mapping::CellState::Free);
        }
    g.computeClearance(5.0, true);
    return g;
  }();
  return grid;
}

void BM_ThetaStarUnreachable(benchmark::State& state) {
  const bool pocket = state.range(1) != 0;
  const mapping::VoxelGrid& grid = pocket ? pocketGrid() : mbsGrid();
  const Query& query = kQueries[state.range(0)];
  const Vec3 goal = pocket ? grid.centre(grid.cellOf(Vec3(40.0, -6.0, 29.0))) : query.goal;
  auto options = searchOptions();
  options.heuristicWeight = 1.5;
  options.maxExpansions = 150000;
  options.partialPath = state.range(2) != 0;
  planning::PathSearcher searcher;
  planning::PathResult result;
  for (auto _ : state) {
    result = searcher.thetaStar(grid, query.start, goal, options);
    benchmark::DoNotOptimize(result.expansions);
  }
  const auto expected =
      pocket ? planning::PathStatus::BudgetExhausted : planning::PathStatus::Found;
  if (result.status != expected) state.SkipWithError(planning::toString(result.status));
  state.counters["expansions"] = static_cast<double>(result.expansions);
}
BENCHMARK(BM_ThetaStarUnreachable)
    ->Args({0, 1, 1})
    ->Args({0, 1, 0})
    ->Args({2, 1, 1})
    ->Args({2, 1, 0})
    ->ArgsProduct({{0, 1, 2, 3, 4}, {0}, {0}})
    ->ArgNames({"query", "pocket", "partial_path"})
    ->Unit(benchmark::kMillisecond);

void BM_SmoothAndTimeParametrise(benchmark::State& state) {
  const mapping::VoxelGrid& grid = mbsGrid();
  const Query& query = kQueries[state.range(0)];
  const auto options = searchOptions();
  const planning::PathResult path = planning::findPathAStar(grid, query.start, query.goal, options);
  planning::TrajectoryLimits limits;
  limits.maxSpeed = 3.0;
  limits.maxAcceleration = 2.0;
  for (auto _ : state) {
    const auto smooth = planning::shortcutPath(grid, path.points, options);
    const planning::Trajectory trajectory(smooth, limits);
    benchmark::DoNotOptimize(trajectory.duration());
  }
  const auto smooth = planning::shortcutPath(grid, path.points, options);
  const planning::Trajectory trajectory(smooth, limits);
  const size_t vertices = smooth.size();
  const double duration = trajectory.duration();
  state.counters["vertices_in"] = static_cast<double>(path.points.size());
  state.counters["vertices_out"] = static_cast<double>(vertices);
  state.counters["duration_s"] = duration;
}
BENCHMARK(BM_SmoothAndTimeParametrise)
    ->DenseRange(0, 4)
    ->ArgName("query")
    ->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
