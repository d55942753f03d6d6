#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

#include "coinspect/core/error.h"
#include "coinspect/planning/routing_exact.h"
#include "routing_test_instances.h"

namespace coinspect::planning {
namespace {

using routing_test::Shape;

// Every order of the non-start nodes, keeping those that respect the problem's end.
double bruteForce(const CostMatrix& costs, const TourProblem& problem) {
  std::vector<int> rest;
  for (int node = 0; node < costs.size(); ++node) {
    if (node != problem.start) rest.push_back(node);
  }
  double best = std::numeric_limits<double>::infinity();
  do {
    std::vector<int> order{problem.start};
    order.insert(order.end(), rest.begin(), rest.end());
    if (problem.end >= 0 && order.back() != problem.end) continue;
    best = std::min(best, tourCost(costs, order, problem.kind));
  } while (std::next_permutation(rest.begin(), rest.end()));
  return best;
}

TEST(HeldKarp, MatchesBruteForceUpToEightNodes) {
  int compared = 0;
  for (Shape shape : {Shape::Euclidean, Shape::Climbing, Shape::Uniform}) {
    for (int n = 1; n <= 8; ++n) {
      const CostMatrix costs = routing_test::randomInstance(shape, n, 100 + n);
      auto problems = routing_test::tourProblems(n);
      if (n == 1) problems.pop_back();  // no end distinct from the start
      for (TourProblem problem : problems) {
        problem.start = n / 2;  // not always node 0
        if (problem.end == problem.start) problem.end = 0;
        SCOPED_TRACE(routing_test::name(shape) + " n=" + std::to_string(n) + " " +
                     routing_test::name(problem));
        const Tour tour = heldKarp(costs, problem);
        EXPECT_TRUE(isValidTour(costs, problem, tour.order));
        EXPECT_NEAR(tour.cost, tourCost(costs, tour.order, problem.kind), 1e-9);
        EXPECT_NEAR(tour.cost, bruteForce(costs, problem), 1e-9);
        ++compared;
      }
    }
  }
  EXPECT_EQ(compared, 3 * (2 + 7 * 3));
}

TEST(HeldKarp, AvoidsForbiddenEdgesLikeBruteForce) {
  for (uint64_t seed = 1; seed <= 10; ++seed) {
    CostMatrix costs = routing_test::randomInstance(Shape::Uniform, 8, seed);
    Rng rng(seed * 77);
    for (int a = 0; a < 8; ++a) {
      for (int b = 0; b < 8; ++b) {
        if (a != b && rng.uniform() < 0.4) costs.forbid(a, b);
      }
    }
    for (const TourProblem& problem : routing_test::tourProblems(8)) {
      SCOPED_TRACE("seed " + std::to_string(seed) + " " + routing_test::name(problem));
      const double expected = bruteForce(costs, problem);
      const Tour tour = heldKarp(costs, problem);
      EXPECT_TRUE(isValidTour(costs, problem, tour.order));
      if (std::isinf(expected)) {
        EXPECT_TRUE(std::isinf(tour.cost));
      } else {
        EXPECT_NEAR(tour.cost, expected, 1e-9);
      }
    }
  }
}

TEST(HeldKarp, ReportsInfinityWhenNoTourIsFeasible) {
  CostMatrix costs(5, 1.0);
  for (int b = 1; b < 5; ++b)
    costs.forbid(0, b);  // nothing can leave the start
  const Tour tour = heldKarp(costs, {TourKind::Closed, 0, -1});
  EXPECT_TRUE(std::isinf(tour.cost));
  EXPECT_TRUE(isValidTour(costs, {TourKind::Closed, 0, -1}, tour.order));
}

TEST(HeldKarp, RejectsTooManyNodesAndBadProblems) {
  EXPECT_THROW(heldKarp(CostMatrix(kHeldKarpMaxNodes + 1, 1.0), {}), InputError);
  EXPECT_THROW(heldKarp(CostMatrix(4, 1.0), {TourKind::Closed, 4, -1}), InputError);
  EXPECT_THROW(heldKarp(CostMatrix(4, 1.0), {TourKind::Closed, 0, 2}), InputError);
  EXPECT_THROW(heldKarp(CostMatrix(4, 1.0), {TourKind::Open, 1, 1}), InputError);
  EXPECT_THROW(heldKarp(CostMatrix(0), {}), InputError);
}

}  // namespace
}  // namespace coinspect::planning
