#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "coinspect/planning/routing_mtsp.h"
#include "coinspect/testing/input_errors.h"
#include "routing_test_instances.h"

namespace coinspect::planning {
namespace {

using routing_test::Shape;

MtspProblem problemWith(int vehicles, int depot, MtspObjective objective) {
  MtspProblem problem;
  for (int v = 0; v < vehicles; ++v)
    problem.starts.push_back(v);
  problem.depot = depot;
  problem.objective = objective;
  return problem;
}

// Cheapest order of `nodes` from `start` (to `depot` if >= 0), by enumeration.
double bestRoute(const CostMatrix& costs, int start, std::vector<int> nodes, int depot) {
  std::sort(nodes.begin(), nodes.end());
  double best = std::numeric_limits<double>::infinity();
  do {
    std::vector<int> route{start};
    route.insert(route.end(), nodes.begin(), nodes.end());
    if (depot >= 0) route.push_back(depot);
    best = std::min(best, tourCost(costs, route, TourKind::Open));
  } while (std::next_permutation(nodes.begin(), nodes.end()));
  return best;
}

// The optimal objective value of a two-vehicle problem: every assignment, every order.
double bruteForce(const CostMatrix& costs, const MtspProblem& problem) {
  std::vector<int> visit;
  for (int node = 0; node < costs.size(); ++node) {
    if (node != problem.starts[0] && node != problem.starts[1] && node != problem.depot)
      visit.push_back(node);
  }
  double best = std::numeric_limits<double>::infinity();
  for (unsigned mask = 0; mask < 1u << visit.size(); ++mask) {
    std::vector<int> first, second;
    for (size_t i = 0; i < visit.size(); ++i)
      (mask >> i & 1 ? first : second).push_back(visit[i]);
    const double a = bestRoute(costs, problem.starts[0], first, problem.depot);
    const double b = bestRoute(costs, problem.starts[1], second, problem.depot);
    best = std::min(best, problem.objective == MtspObjective::MinMax ? std::max(a, b) : a + b);
  }
  return best;
}

TEST(Mtsp, RejectsBadProblems) {
  using coinspect::testing::messageOf;
  const CostMatrix costs(5, 1.0);
  EXPECT_MENTIONS(messageOf([&] { solveMtsp(costs, MtspProblem{}); }), "no vehicle");
  EXPECT_MENTIONS(messageOf([&] { solveMtsp(costs, MtspProblem{{0, 0}, -1}); }), "starts[1]");
  EXPECT_MENTIONS(messageOf([&] { solveMtsp(costs, MtspProblem{{0, 9}, -1}); }), "starts[1]");
  EXPECT_MENTIONS(messageOf([&] { solveMtsp(costs, MtspProblem{{0, 1}, 1}); }), "also a start");
  MtspSolution broken{{{0, 2, 3}, {1, 2, 4}}, {}, 0, 0};  // node 2 twice
  EXPECT_MENTIONS(messageOf([&] {
                    improveMtsp(costs, MtspProblem{{0, 1}, -1}, broken);
                  }),
                  "every node once");
}

// 2 vehicles, 7 nodes to visit, 16 instances per objective (open routes and a common depot):
// plain local search is on average within 5 % of the optimum and never beyond 15 %; with 10
// kicks of iterated local search, within 1 % on average and 5 % always.
TEST(Mtsp, HeuristicIsNearBruteForce) {
  LocalSearchOptions kicked;
  kicked.kicks = 10;
  for (MtspObjective objective : {MtspObjective::MinSum, MtspObjective::MinMax}) {
    double plainGaps = 0.0, kickedGaps = 0.0;
    int instances = 0;
    for (int depot : {-1, 9}) {
      for (uint64_t seed = 1; seed <= 8; ++seed) {
        const CostMatrix costs = routing_test::randomInstance(Shape::Climbing, 10, seed + 60);
        const MtspProblem problem = problemWith(2, depot, objective);
        SCOPED_TRACE("seed " + std::to_string(seed) + " depot " + std::to_string(depot) +
                     (objective == MtspObjective::MinMax ? " min-max" : " min-sum"));
        const double optimum = bruteForce(costs, problem);
        const auto gap = [&](const MtspSolution& solution) {
          EXPECT_TRUE(isValidMtsp(costs, problem, solution));
          const double value =
              objective == MtspObjective::MinMax ? solution.makespan : solution.totalCost;
          EXPECT_GE(value, optimum - 1e-9);
          return value / optimum - 1.0;
        };
        const double plain = gap(solveMtsp(costs, problem));
        const double withKicks = gap(solveMtsp(costs, problem, kicked));
        EXPECT_LE(plain, 0.15);
        EXPECT_LE(withKicks, 0.05);
        EXPECT_LE(withKicks, plain + 1e-12);  // kicks keep the better solution
        plainGaps += plain;
        kickedGaps += withKicks;
        ++instances;
      }
    }
    EXPECT_LE(plainGaps / instances, 0.05);
    EXPECT_LE(kickedGaps / instances, 0.01);
  }
}

// Two vehicles at the centre of a ring of 16 points, open routes: one vehicle flying the whole
// ring costs least in total, splitting the ring between both finishes earliest.
TEST(Mtsp, ObjectivesTradeTotalAgainstMakespan) {
  std::vector<Eigen::Vector3d> points{{0, 0, 0}, {0, 0, 0}};
  for (int i = 0; i < 16; ++i) {
    const double angle = 2.0 * M_PI * i / 16;
    points.emplace_back(50 * std::cos(angle), 50 * std::sin(angle), 0);
  }
  const CostMatrix costs = euclideanCostMatrix(points);
  const MtspSolution sum = solveMtsp(costs, problemWith(2, -1, MtspObjective::MinSum));
  const MtspSolution max = solveMtsp(costs, problemWith(2, -1, MtspObjective::MinMax));
  EXPECT_LT(max.makespan, sum.makespan - 50.0);
  EXPECT_LT(sum.totalCost, max.totalCost - 10.0);
  const double chord = 2 * 50 * std::sin(M_PI / 16);
  EXPECT_NEAR(sum.totalCost, 50 + 15 * chord, 1e-6);  // out once, then around
  EXPECT_NEAR(max.makespan, 50 + 7 * chord, 1e-6);    // 8 points each
}

TEST(Mtsp, VisitsEveryNodeOnceAndNeverWorsensItsConstruction) {
  for (MtspObjective objective : {MtspObjective::MinSum, MtspObjective::MinMax}) {
    for (int depot : {-1, 4}) {
      const CostMatrix costs = routing_test::randomInstance(Shape::Climbing, 70, 5);
      const MtspProblem problem = problemWith(4, depot, objective);
      const MtspSolution built = constructMtsp(costs, problem);
      RoutingStats stats;
      const MtspSolution solution = improveMtsp(costs, problem, built, {}, &stats);
      EXPECT_TRUE(isValidMtsp(costs, problem, built));
      EXPECT_TRUE(isValidMtsp(costs, problem, solution));
      EXPECT_FALSE(mtspBetter(objective, built, solution));
      MtspSolution recomputed = solution;
      evaluateMtsp(costs, recomputed);
      EXPECT_EQ(recomputed.routeCosts, solution.routeCosts);
      EXPECT_GT(stats.evaluations, 0);
    }
  }
}

TEST(Mtsp, IsDeterministicAndHonoursTheBudget) {
  const CostMatrix costs = routing_test::randomInstance(Shape::Uniform, 60, 9);
  const MtspProblem problem = problemWith(3, -1, MtspObjective::MinMax);
  const MtspSolution a = solveMtsp(costs, problem);
  const MtspSolution b = solveMtsp(costs, problem);
  EXPECT_EQ(a.routes, b.routes);
  LocalSearchOptions limited;
  limited.maxEvaluations = 1000;
  RoutingStats stats;
  const MtspSolution cut = solveMtsp(costs, problem, limited, &stats);
  EXPECT_EQ(stats.evaluations, 1000);
  EXPECT_TRUE(isValidMtsp(costs, problem, cut));
  EXPECT_FALSE(mtspBetter(problem.objective, cut, a));  // the same moves, stopped earlier
}

// A fifth of the edges forbidden at random; open routes always have a feasible solution here.
TEST(Mtsp, AvoidsForbiddenEdges) {
  for (uint64_t seed = 1; seed <= 5; ++seed) {
    CostMatrix costs = routing_test::randomInstance(Shape::Euclidean, 40, seed);
    Rng rng(seed + 900);
    for (int a = 0; a < 40; ++a) {
      for (int b = 0; b < 40; ++b) {
        if (a != b && rng.uniform() < 0.2) costs.forbid(a, b);
      }
    }
    for (MtspObjective objective : {MtspObjective::MinSum, MtspObjective::MinMax}) {
      const MtspProblem problem = problemWith(3, -1, objective);
      const MtspSolution solution = solveMtsp(costs, problem);
      EXPECT_TRUE(isValidMtsp(costs, problem, solution));
      EXPECT_TRUE(std::isfinite(solution.totalCost)) << "seed " << seed;
    }
  }
}

TEST(Mtsp, HandlesVehiclesWithNothingToDo) {
  const CostMatrix costs = routing_test::randomInstance(Shape::Euclidean, 4, 3);
  const MtspProblem problem = problemWith(3, 3, MtspObjective::MinMax);  // one node, 3 vehicles
  const MtspSolution solution = solveMtsp(costs, problem);
  EXPECT_TRUE(isValidMtsp(costs, problem, solution));
  const MtspProblem none = problemWith(4, -1, MtspObjective::MinSum);  // every node a start
  const MtspSolution idle = solveMtsp(costs, none);
  EXPECT_TRUE(isValidMtsp(costs, none, idle));
  EXPECT_EQ(idle.totalCost, 0.0);
}

}  // namespace
}  // namespace coinspect::planning
