#include "coinspect/planning/path_search.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <queue>
#include <thread>

#include "coinspect/core/random.h"

namespace coinspect::planning {
namespace {

using mapping::CellState;
constexpr double kInf = std::numeric_limits<double>::infinity();

// The rule and costs of path_search.h, written again independently for the oracle.
bool oracleTraversable(const VoxelGrid& grid, const Index3& c, const PathSearchOptions& o) {
  if (!grid.contains(c)) return false;
  if (grid.state(c) == CellState::Occupied) return false;
  if (grid.state(c) == CellState::Unknown && o.unknown == UnknownPolicy::Blocked) return false;
  if (grid.clearance(c) < o.clearance) return false;
  for (const auto& sphere : o.avoid)
    if ((grid.centre(c) - sphere.centre).norm() < sphere.radius) return false;
  return true;
}

double oracleMultiplier(const VoxelGrid& grid, const Index3& c, const PathSearchOptions& o) {
  double m = 1.0;
  if (o.softClearance > 0.0)
    m += o.softWeight * std::max(0.0, 1.0 - grid.clearance(c) / o.softClearance);
  if (o.unknown == UnknownPolicy::FreeWithCost && grid.state(c) == CellState::Unknown)
    m += o.unknownPenalty;
  return m;
}

// Brute-force Dijkstra over every cell, 26-connected, no corner cutting: least cost from `from`
// to every cell.
std::vector<double> dijkstra(const VoxelGrid& grid, const Index3& from,
                             const PathSearchOptions& o) {
  std::vector<double> dist(grid.cellCount(), kInf);
  using Item = std::pair<double, size_t>;
  std::priority_queue<Item, std::vector<Item>, std::greater<>> queue;
  dist[grid.linear(from)] = 0.0;
  queue.push({0.0, grid.linear(from)});
  const Index3 size = grid.size();
  while (!queue.empty()) {
    const auto [d, index] = queue.top();
    queue.pop();
    if (d > dist[index]) continue;
    const Index3 c(index % size.x(), (index / size.x()) % size.y(), index / (size.x() * size.y()));
    for (int dz = -1; dz <= 1; ++dz)
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
          const Index3 delta(dx, dy, dz);
          if (delta == Index3::Zero()) continue;
          bool allowed = true;
          for (int sz = 0; sz <= std::abs(dz); ++sz)
            for (int sy = 0; sy <= std::abs(dy); ++sy)
              for (int sx = 0; sx <= std::abs(dx); ++sx)
                allowed =
                    allowed && oracleTraversable(grid, c + Index3(sx * dx, sy * dy, sz * dz), o);
          if (!allowed) continue;
          const Index3 n = c + delta;
          const double cost = delta.cast<double>().norm() * grid.resolution() * 0.5 *
                              (oracleMultiplier(grid, c, o) + oracleMultiplier(grid, n, o));
          if (d + cost < dist[grid.linear(n)]) {
            dist[grid.linear(n)] = d + cost;
            queue.push({d + cost, grid.linear(n)});
          }
        }
  }
  return dist;
}

VoxelGrid randomGrid(uint64_t seed, double occupied, double unknown, bool unknownBlocks) {
  Rng rng(seed);
  VoxelGrid grid(Vec3(-1.0, 2.0, 0.0), 0.5, Index3(14, 11, 6), CellState::Free);
  for (int z = 0; z < 6; ++z)
    for (int y = 0; y < 11; ++y)
      for (int x = 0; x < 14; ++x) {
        const double u = rng.uniform();
        if (u < occupied)
          grid.set(Index3(x, y, z), CellState::Occupied);
        else if (u < occupied + unknown)
          grid.set(Index3(x, y, z), CellState::Unknown);
      }
  grid.computeClearance(10.0, unknownBlocks);
  return grid;
}

// Every point of every segment (sampled finely) lies in a traversable cell; returns the
// sampled weighted length.
double checkPolyline(const VoxelGrid& grid, const std::vector<Vec3>& points,
                     const PathSearchOptions& o) {
  double cost = 0.0;
  for (size_t i = 1; i < points.size(); ++i) {
    const Vec3 a = points[i - 1], b = points[i];
    const int samples = 2000;
    for (int s = 0; s < samples; ++s) {
      const Vec3 p = a + (s + 0.5) / samples * (b - a);
      const Index3 c = grid.cellOf(p);
      EXPECT_TRUE(oracleTraversable(grid, c, o)) << "segment " << i << " at " << p.transpose();
      cost += oracleMultiplier(grid, c, o) * (b - a).norm() / samples;
    }
  }
  return cost;
}

struct Case {
  UnknownPolicy unknown;
  double clearance, softClearance, softWeight;
};

// A* is optimal (equals the oracle's least cost); Theta* is never worse than the grid path (not a
// theorem, but what its neighbour comparison gives on all these cases), usually shorter, and never
// shorter than the straight line; both respect clearance and the unknown policy on every point.
TEST(PathSearch, AStarAndThetaStarAgainstBruteForceDijkstra) {
  const Case cases[] = {{UnknownPolicy::Blocked, 0.0, 0.0, 0.0},
                        {UnknownPolicy::Blocked, 0.5, 0.0, 0.0},
                        {UnknownPolicy::Free, 0.0, 1.2, 2.0},
                        {UnknownPolicy::FreeWithCost, 0.5, 1.0, 1.0},
                        {UnknownPolicy::FreeWithCost, 0.0, 0.0, 0.0}};
  int found = 0, checked = 0;
  int thetaShorter = 0;
  for (uint64_t seed = 1; seed <= 8; ++seed)
    for (const auto& c : cases) {
      PathSearchOptions o;
      o.unknown = c.unknown;
      o.clearance = c.clearance;
      o.softClearance = c.softClearance;
      o.softWeight = c.softWeight;
      o.snapRadius = 0;
      const VoxelGrid grid = randomGrid(seed, 0.12, 0.1, c.unknown == UnknownPolicy::Blocked);
      Rng rng(seed * 100 + 7);
      PathSearcher searcher;
      for (int q = 0; q < 6; ++q) {
        Index3 s, g;
        do {
          s = Index3(rng.below(14), rng.below(11), rng.below(6));
        } while (!oracleTraversable(grid, s, o));
        do {
          g = Index3(rng.below(14), rng.below(11), rng.below(6));
        } while (!oracleTraversable(grid, g, o));
        const double best = dijkstra(grid, s, o)[grid.linear(g)];
        const PathResult a = searcher.aStar(grid, grid.centre(s), grid.centre(g), o);
        const PathResult t = searcher.thetaStar(grid, grid.centre(s), grid.centre(g), o);
        ++checked;
        if (best == kInf) {
          EXPECT_EQ(a.status, PathStatus::NoPath);
          EXPECT_EQ(t.status, PathStatus::NoPath);
          continue;
        }
        ++found;
        ASSERT_EQ(a.status, PathStatus::Found);
        ASSERT_EQ(t.status, PathStatus::Found);
        EXPECT_NEAR(a.cost, best, 1e-9 * (1.0 + best));
        for (size_t i = 1; i < a.cells.size(); ++i)
          EXPECT_LE((a.cells[i] - a.cells[i - 1]).cwiseAbs().maxCoeff(), 1);
        EXPECT_NEAR(checkPolyline(grid, a.points, o), a.cost, 0.01 * (1.0 + a.cost));
        EXPECT_NEAR(checkPolyline(grid, t.points, o), t.cost, 0.01 * (1.0 + t.cost));
        EXPECT_GE(t.cost, (grid.centre(g) - grid.centre(s)).norm() - 1e-9);
        EXPECT_LE(t.cost, best * (1.0 + 1e-9)) << t.cost / best;
        if (t.cost < best - 1e-6) ++thetaShorter;
        // Weighted A*: bounded suboptimality.
        PathSearchOptions weighted = o;
        weighted.heuristicWeight = 1.5;
        const PathResult w = searcher.aStar(grid, grid.centre(s), grid.centre(g), weighted);
        ASSERT_EQ(w.status, PathStatus::Found);
        EXPECT_GE(w.cost, best - 1e-9);
        EXPECT_LE(w.cost, 1.5 * best + 1e-9);
      }
    }
  EXPECT_GT(found, checked / 2);  // the random grids must mostly be solvable to test anything
  EXPECT_GT(thetaShorter, found / 2);
}

// reachableCells marks exactly the cells the brute-force Dijkstra (26-connected, no corner
// cutting) reaches from the start.
TEST(PathSearch, ReachableCellsAreThoseASearchReaches) {
  int reachable = 0, unreachable = 0;
  for (uint64_t seed = 1; seed <= 6; ++seed) {
    PathSearchOptions o;
    o.clearance = seed % 2 ? 0.0 : 0.5;
    o.snapRadius = 0;
    const VoxelGrid grid = randomGrid(seed, 0.25, 0.1, true);
    Rng rng(seed * 31 + 1);
    Index3 s;
    do {
      s = Index3(rng.below(14), rng.below(11), rng.below(6));
    } while (!oracleTraversable(grid, s, o));
    const auto best = dijkstra(grid, s, o);
    const auto reached = reachableCells(grid, grid.centre(s), o);
    ASSERT_EQ(reached.size(), grid.cellCount());
    for (size_t i = 0; i < best.size(); ++i) {
      EXPECT_EQ(reached[i] != 0, best[i] < kInf) << "seed " << seed << " cell " << i;
      (best[i] < kInf ? reachable : unreachable) += 1;
    }
  }
  EXPECT_GT(reachable, 100);  // both kinds must occur for the comparison to mean anything
  EXPECT_GT(unreachable, 100);
  // A start with no traversable cell within the snap radius reaches nothing.
  VoxelGrid solid(Vec3::Zero(), 1.0, Index3(4, 4, 4), CellState::Occupied);
  solid.computeClearance(2.0, true);
  const auto none = reachableCells(solid, Vec3(2, 2, 2), PathSearchOptions{});
  EXPECT_TRUE(std::all_of(none.begin(), none.end(), [](uint8_t r) { return r == 0; }));
}

// The cache answers every question as reachableCells does: from starts in one component, in
// another, with no traversable cell near, under other options and after the grid changed (a new
// version). It floods again only when the answer could differ.
TEST(PathSearch, ReachableCellsCacheAnswersAsAFreshFloodDoes) {
  size_t questions = 0, floods = 0;
  for (uint64_t seed = 1; seed <= 4; ++seed) {
    VoxelGrid grid = randomGrid(seed, 0.3, 0.1, true);
    ReachableCellsCache cache;
    Rng rng(seed * 17 + 3);
    uint64_t version = 0;
    for (int q = 0; q < 60; ++q) {
      PathSearchOptions o;
      o.snapRadius = static_cast<int>(rng.below(3));
      o.clearance = rng.below(4) == 0 ? 0.5 : 0.0;
      if (rng.below(5) == 0) o.avoid.push_back({grid.centre(Index3(7, 5, 3)), 2.0});
      if (rng.below(10) == 0) {  // the map changed: a cell flips, the grid gets a new version
        const Index3 c(rng.below(14), rng.below(11), rng.below(6));
        grid.set(c, grid.state(c) == CellState::Free ? CellState::Occupied : CellState::Free);
        grid.computeClearance(2.0, true);
        ++version;
      }
      const Vec3 start = grid.centre(Index3(rng.below(14), rng.below(11), rng.below(6)));
      ASSERT_EQ(cache.from(grid, version, start, o), reachableCells(grid, start, o))
          << "seed " << seed << " question " << q;
      ++questions;
    }
    floods += cache.floods();
  }
  EXPECT_LT(floods, questions);  // some answers came from the kept flood
  EXPECT_GT(floods, questions / 10);

  // Two starts in one room share a flood; the other room needs its own; back again, another.
  VoxelGrid rooms(Vec3::Zero(), 1.0, Index3(9, 4, 4), CellState::Free);
  for (int z = 0; z < 4; ++z)
    for (int y = 0; y < 4; ++y)
      rooms.set(Index3(4, y, z), CellState::Occupied);
  rooms.computeClearance(2.0, true);
  ReachableCellsCache cache;
  PathSearchOptions o;
  o.snapRadius = 0;
  const std::vector<Vec3> starts = {
      {0.5, 0.5, 0.5}, {3.5, 3.5, 3.5}, {6.5, 1.5, 1.5}, {1.5, 2.5, 0.5}};
  const std::vector<size_t> floodsAfter = {1, 1, 2, 3};
  for (size_t i = 0; i < starts.size(); ++i) {
    EXPECT_EQ(cache.from(rooms, 0, starts[i], o), reachableCells(rooms, starts[i], o));
    EXPECT_EQ(cache.floods(), floodsAfter[i]) << "start " << i;
  }
}

VoxelGrid wallGrid() {
  // 20 x 10 x 5 cells of 1 m, a wall at x = 10 with a one-cell unknown window at (10, 5, 2).
  VoxelGrid grid(Vec3::Zero(), 1.0, Index3(20, 10, 5), CellState::Free);
  for (int z = 0; z < 5; ++z)
    for (int y = 0; y < 10; ++y)
      grid.set(Index3(10, y, z), CellState::Occupied);
  grid.set(Index3(10, 5, 2), CellState::Unknown);
  grid.computeClearance(5.0, false);
  return grid;
}

TEST(PathSearch, UnknownPolicyDecidesWhetherUnknownCellsAreEntered) {
  const VoxelGrid grid = wallGrid();
  const Vec3 start(2.5, 5.5, 2.5), goal(17.5, 5.5, 2.5);
  PathSearchOptions o;
  o.unknown = UnknownPolicy::Blocked;
  EXPECT_EQ(findPathAStar(grid, start, goal, o).status, PathStatus::NoPath);
  EXPECT_EQ(findPathThetaStar(grid, start, goal, o).status, PathStatus::NoPath);
  o.unknown = UnknownPolicy::Free;
  const PathResult free = findPathAStar(grid, start, goal, o);
  ASSERT_EQ(free.status, PathStatus::Found);
  EXPECT_NEAR(free.cost, 15.0, 1e-9);
  o.unknown = UnknownPolicy::FreeWithCost;
  o.unknownPenalty = 3.0;
  const PathResult costly = findPathThetaStar(grid, start, goal, o);
  ASSERT_EQ(costly.status, PathStatus::Found);
  EXPECT_NEAR(costly.cost, 15.0 + 3.0, 1e-6);  // one metre through the unknown cell at 4x
  EXPECT_EQ(grid.state(grid.cellOf(Vec3(10.5, 5.5, 2.5))), CellState::Unknown);
}

TEST(PathSearch, RequiredClearanceKeepsThePathAwayFromObstacles) {
  // A pillar in the middle; the straight line passes 1 m from it.
  VoxelGrid grid(Vec3::Zero(), 0.5, Index3(40, 20, 4), CellState::Free);
  for (int z = 0; z < 4; ++z)
    grid.set(Index3(20, 8, z), CellState::Occupied);
  grid.computeClearance(10.0, false);
  const Vec3 start(1.25, 5.25, 1.25), goal(18.75, 5.25, 1.25);
  PathSearchOptions o;
  EXPECT_NEAR(findPathThetaStar(grid, start, goal, o).cost, 17.5, 1e-6);
  o.clearance = 2.0;
  for (const auto& result :
       {findPathAStar(grid, start, goal, o), findPathThetaStar(grid, start, goal, o)}) {
    ASSERT_EQ(result.status, PathStatus::Found);
    EXPECT_GT(result.cost, 17.5 + 0.1);
    checkPolyline(grid, result.points, o);
  }
}

TEST(PathSearch, AvoidSpheresKeepThePathOutOfSpaceTheMapDoesNotHold) {
  // Open space; a robot holds on the straight line (x = 10): the path goes around it, and every
  // point of it stays outside the sphere less the half cell diagonal (a point may lie anywhere
  // in a cell whose centre is outside).
  VoxelGrid grid(Vec3::Zero(), 0.5, Index3(40, 20, 8), CellState::Free);
  grid.computeClearance(10.0, false);
  const Vec3 start(1.25, 5.25, 2.25), goal(18.75, 5.25, 2.25);
  PathSearchOptions o;
  o.avoid.push_back({Vec3(10.0, 5.25, 2.25), 2.5});
  EXPECT_FALSE(segmentTraversable(grid, start, goal, o));
  for (const auto& result :
       {findPathAStar(grid, start, goal, o), findPathThetaStar(grid, start, goal, o)}) {
    ASSERT_EQ(result.status, PathStatus::Found);
    EXPECT_GT(result.cost, 17.5 + 0.5);
    checkPolyline(grid, result.points, o);
    for (size_t i = 1; i < result.points.size(); ++i)
      for (double f = 0.0; f <= 1.0; f += 0.01) {
        const Vec3 p = result.points[i - 1] + f * (result.points[i] - result.points[i - 1]);
        EXPECT_GE((p - o.avoid[0].centre).norm(), 2.5 - 0.5 * 0.5 * std::sqrt(3.0) - 1e-9);
      }
  }
  o.avoid.clear();
  EXPECT_TRUE(segmentTraversable(grid, start, goal, o));
}

TEST(PathSearch, StatusesForBlockedEndpointsAndBudget) {
  VoxelGrid grid = wallGrid();
  grid.set(Index3(10, 5, 2), CellState::Occupied);
  grid.computeClearance(5.0, false);
  PathSearchOptions o;
  // The wall is closed: no path, and the search says so after exploring the whole side.
  EXPECT_EQ(findPathAStar(grid, Vec3(2.5, 5.5, 2.5), Vec3(17.5, 5.5, 2.5), o).status,
            PathStatus::NoPath);
  // Inside the wall: snapped to the nearest free cell beside it.
  const PathResult snapped = findPathAStar(grid, Vec3(10.6, 5.5, 2.5), Vec3(17.5, 5.5, 2.5), o);
  ASSERT_EQ(snapped.status, PathStatus::Found);
  EXPECT_TRUE(snapped.startSnapped);
  EXPECT_EQ(snapped.points.front(), Vec3(10.6, 5.5, 2.5));  // the path starts where the robot is
  EXPECT_EQ(snapped.cells.front(), Index3(11, 5, 2));
  // Deep inside an obstacle (beyond the snap radius) or outside the grid.
  VoxelGrid solid(Vec3::Zero(), 1.0, Index3(20, 20, 20), CellState::Occupied);
  solid.set(Index3(0, 0, 0), CellState::Free);
  solid.computeClearance(5.0, false);
  EXPECT_EQ(findPathAStar(solid, Vec3(10.5, 10.5, 10.5), Vec3(0.5, 0.5, 0.5), o).status,
            PathStatus::StartBlocked);
  EXPECT_EQ(findPathThetaStar(solid, Vec3(0.5, 0.5, 0.5), Vec3(10.5, 10.5, 10.5), o).status,
            PathStatus::GoalBlocked);
  // A small budget: the path to the expanded cell nearest the goal.
  o.maxExpansions = 40;
  VoxelGrid openGrid(Vec3::Zero(), 1.0, Index3(60, 60, 4), CellState::Free);
  openGrid.computeClearance(5.0, false);
  for (const bool anyAngle : {false, true}) {
    PathSearcher searcher;
    const Vec3 start(0.5, 0.5, 0.5), goal(59.5, 59.5, 3.5);
    const PathResult partial = anyAngle ? searcher.thetaStar(openGrid, start, goal, o)
                                        : searcher.aStar(openGrid, start, goal, o);
    ASSERT_EQ(partial.status, PathStatus::BudgetExhausted);
    EXPECT_EQ(partial.expansions, 40u);
    ASSERT_GE(partial.points.size(), 2u);
    EXPECT_LT((partial.points.back() - goal).norm(), (start - goal).norm() - 5.0);
  }
}

// Without partial paths a search may prove an enclosed goal unreachable by flooding instead of
// searching: every query still ends with the status and expansion count of the full search, and
// found paths are the same. Grids dense enough for many pockets, budgets below and above their
// components (NoPath and BudgetExhausted), one searcher for both kinds of query in turn.
TEST(PathSearch, WithoutPartialPathsEveryQueryEndsAsTheFullSearchDoes) {
  int found = 0, noPath = 0, exhausted = 0;
  PathSearcher searcher;
  for (uint64_t seed = 1; seed <= 12; ++seed) {
    PathSearchOptions full;
    full.clearance = seed % 3 == 0 ? 0.5 : 0.0;
    full.unknown = seed % 4 == 1 ? UnknownPolicy::FreeWithCost : UnknownPolicy::Blocked;
    full.snapRadius = seed % 2 ? 0 : 2;
    full.heuristicWeight = seed % 5 == 0 ? 1.5 : 1.0;
    const VoxelGrid grid = randomGrid(seed, 0.4, 0.1, full.unknown == UnknownPolicy::Blocked);
    Rng rng(seed * 17 + 3);
    for (int q = 0; q < 40; ++q) {
      full.maxExpansions = std::vector<size_t>{1, 20, 60, 1000000}[q % 4];
      PathSearchOptions lean = full;
      lean.partialPath = false;
      const auto traversable = [&] {
        Index3 c;
        do {
          c = Index3(rng.below(14), rng.below(11), rng.below(6));
        } while (!oracleTraversable(grid, c, full));
        return grid.centre(c);
      };
      const Vec3 s = traversable(), g = traversable();
      for (const bool anyAngle : {false, true}) {
        const auto run = [&](const PathSearchOptions& o) {
          return anyAngle ? searcher.thetaStar(grid, s, g, o) : searcher.aStar(grid, s, g, o);
        };
        const PathResult a = run(full), b = run(lean);
        ASSERT_EQ(a.status, b.status) << "seed " << seed << " query " << q;
        EXPECT_EQ(a.expansions, b.expansions) << "seed " << seed << " query " << q;
        EXPECT_EQ(a.startSnapped, b.startSnapped);
        EXPECT_EQ(a.goalSnapped, b.goalSnapped);
        if (a.status == PathStatus::Found) {
          ++found;
          EXPECT_EQ(a.points, b.points);
          EXPECT_EQ(a.cells, b.cells);
          EXPECT_EQ(a.cost, b.cost);
        } else if (a.status == PathStatus::NoPath) {
          ++noPath;
        } else if (a.status == PathStatus::BudgetExhausted && b.points.empty()) {
          ++exhausted;  // the proof's answer, without the partial path
        }
      }
    }
  }
  // Each outcome must occur for the comparison to mean anything.
  EXPECT_GT(found, 200);
  EXPECT_GT(noPath, 25);
  EXPECT_GT(exhausted, 15);
}

// Same query, same answer, also when the searcher is reused across grids and queries: a
// smaller grid (924 cells) after a larger one (1000) reads the cells the larger one stamped.
TEST(PathSearch, ReusedSearcherGivesIdenticalResults) {
  const VoxelGrid grid = randomGrid(3, 0.15, 0.0, false);
  const VoxelGrid other = wallGrid();
  PathSearchOptions o;
  PathSearcher searcher;
  const Vec3 s = grid.centre(Index3(0, 0, 0)), g = grid.centre(Index3(13, 10, 5));
  const Vec3 west(2.5, 5.5, 2.5), east(17.5, 5.5, 2.5);
  const PathResult first = searcher.thetaStar(grid, s, g, o);
  const PathResult wall = searcher.aStar(other, west, east, o);
  EXPECT_EQ(wall.status, PathStatus::NoPath);        // the unknown window is closed
  EXPECT_GT(wall.expansions, grid.cellCount() / 4);  // it stamped much of the shared cells
  searcher.thetaStar(grid, g, s, o);
  const PathResult again = searcher.thetaStar(grid, s, g, o);
  EXPECT_EQ(first.points, again.points);
  EXPECT_EQ(first.cost, again.cost);
  EXPECT_EQ(first.expansions, again.expansions);
  PathSearchOptions throughWindow;
  throughWindow.unknown = UnknownPolicy::Free;
  const PathResult fresh = PathSearcher().aStar(other, west, east, throughWindow);
  const PathResult wallAgain = searcher.aStar(other, west, east, throughWindow);
  EXPECT_EQ(fresh.status, PathStatus::Found);
  EXPECT_EQ(fresh.points, wallAgain.points);
  EXPECT_EQ(fresh.expansions, wallAgain.expansions);
}

// Units deciding on one thread share its searcher; another thread has its own.
TEST(PathSearch, ThreadPathSearcherIsOnePerThread) {
  PathSearcher* here = &threadPathSearcher();
  EXPECT_EQ(here, &threadPathSearcher());
  PathSearcher* there = nullptr;
  std::thread([&] { there = &threadPathSearcher(); }).join();
  EXPECT_NE(here, there);
}

TEST(PathSearch, SegmentCheckSeesCornerGrazes) {
  VoxelGrid grid(Vec3::Zero(), 1.0, Index3(4, 4, 1), CellState::Free);
  grid.set(Index3(1, 0, 0), CellState::Occupied);
  grid.computeClearance(5.0, false);
  PathSearchOptions o;
  // (0,0) -> (1,1) diagonally touches the corner of the occupied cell (1,0).
  EXPECT_FALSE(segmentTraversable(grid, Vec3(0.5, 0.5, 0.5), Vec3(1.5, 1.5, 0.5), o));
  double cost = 0.0;
  EXPECT_TRUE(segmentTraversable(grid, Vec3(0.5, 1.5, 0.5), Vec3(3.5, 2.5, 0.5), o, &cost));
  EXPECT_NEAR(cost, std::sqrt(10.0), 1e-12);
}

}  // namespace
}  // namespace coinspect::planning
