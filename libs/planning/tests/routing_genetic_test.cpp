#include <gtest/gtest.h>

#include "coinspect/planning/routing_exact.h"
#include "coinspect/planning/routing_genetic.h"
#include "coinspect/testing/input_errors.h"
#include "routing_test_instances.h"

namespace coinspect::planning {
namespace {

using routing_test::Shape;

MtspProblem threeVehicles(MtspObjective objective) {
  MtspProblem problem;
  problem.starts = {0, 1, 2};
  problem.objective = objective;
  return problem;
}

GeneticOptions small(uint64_t seed) {
  GeneticOptions options;
  options.seed = seed;
  options.population = 10;
  options.generations = 10;
  return options;
}

TEST(Genetic, IsReproducibleBySeed) {
  const CostMatrix costs = routing_test::randomInstance(Shape::Climbing, 40, 21);
  const MtspProblem problem = threeVehicles(MtspObjective::MinMax);
  const GeneticResult a = geneticMtsp(costs, problem, small(5));
  const GeneticResult b = geneticMtsp(costs, problem, small(5));
  EXPECT_EQ(a.best.routes, b.best.routes);
  EXPECT_EQ(a.evaluations, b.evaluations);
  EXPECT_TRUE(isValidMtsp(costs, problem, a.best));
  EXPECT_TRUE(isValidMtsp(costs, problem, a.initialBest));
}

// Never worse than the initial population's best (elitism), for both objectives and a depot.
TEST(Genetic, KeepsTheInitialBest) {
  for (MtspObjective objective : {MtspObjective::MinSum, MtspObjective::MinMax}) {
    for (int depot : {-1, 39}) {
      const CostMatrix costs = routing_test::randomInstance(Shape::Uniform, 40, 22);
      MtspProblem problem = threeVehicles(objective);
      problem.depot = depot;
      const GeneticResult result = geneticMtsp(costs, problem, small(6));
      EXPECT_TRUE(isValidMtsp(costs, problem, result.best));
      EXPECT_FALSE(mtspBetter(objective, result.initialBest, result.best));
    }
  }
}

// Without local search and without the heuristic individual, crossover and mutation alone must
// beat the best of a random initial population.
TEST(Genetic, EvolutionImprovesARandomPopulation) {
  const CostMatrix costs = routing_test::randomInstance(Shape::Euclidean, 30, 23);
  GeneticOptions options;
  options.memetic = false;
  options.seedWithHeuristic = false;
  options.generations = 60;
  double initial = 0.0;
  const Tour tour = geneticTsp(costs, {}, options, &initial);
  EXPECT_TRUE(isValidTour(costs, {}, tour.order));
  EXPECT_LT(tour.cost, 0.8 * initial);
}

// The memetic GA on small TSPs and ATSPs: within 1 % of Held-Karp.
TEST(Genetic, SolvesSmallToursNearlyOptimally) {
  for (Shape shape : {Shape::Euclidean, Shape::Uniform}) {
    for (const TourProblem& problem : routing_test::tourProblems(11)) {
      const CostMatrix costs = routing_test::randomInstance(shape, 11, 24);
      SCOPED_TRACE(routing_test::name(shape) + " " + routing_test::name(problem));
      const Tour tour = geneticTsp(costs, problem, small(7));
      EXPECT_TRUE(isValidTour(costs, problem, tour.order));
      EXPECT_LE(tour.cost, heldKarp(costs, problem).cost * 1.01);
    }
  }
}

TEST(Genetic, RejectsBadOptions) {
  using coinspect::testing::messageOf;
  const CostMatrix costs(6, 1.0);
  GeneticOptions options;
  options.population = 0;
  EXPECT_MENTIONS(messageOf([&] { geneticTsp(costs, {}, options); }), "population");
  options = {};
  options.mutationRate = 1.5;
  EXPECT_MENTIONS(messageOf([&] { geneticTsp(costs, {}, options); }), "mutationRate");
  options = {};
  options.tournament = 0;
  EXPECT_MENTIONS(messageOf([&] { geneticTsp(costs, {}, options); }), "tournament");
}

}  // namespace
}  // namespace coinspect::planning
