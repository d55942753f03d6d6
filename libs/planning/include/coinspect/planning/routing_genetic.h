// A memetic genetic algorithm for TSP and mTSP, reproducible by seed.
//
// A chromosome is a "giant tour": the visited nodes of all routes, vehicle after vehicle. It is
// decoded by an optimal split into consecutive routes (dynamic programming for the objective),
// then, when `memetic` is on, improved by the local search of routing_mtsp.h and encoded again.
// Parents are picked by tournament, crossed by order crossover (OX) and mutated (swap of two
// nodes or reversal of a stretch); the best individual always survives (elitism).
#pragma once

#include <cstdint>

#include "coinspect/planning/routing_mtsp.h"

namespace coinspect::planning {

struct GeneticOptions {
  uint64_t seed = 1;
  int population = 24;
  int generations = 40;
  int tournament = 2;             // individuals drawn per parent selection
  double mutationRate = 0.3;      // probability that a child is mutated
  bool memetic = true;            // local search on every child
  bool seedWithHeuristic = true;  // individual 0 is solveMtsp's answer, the others random
  LocalSearchOptions search;      // the memetic step's options (its budget is per child)
};

struct GeneticResult {
  MtspSolution best;
  MtspSolution initialBest;  // best of the initial population (after its memetic step)
  int64_t evaluations = 0;   // local-search move evaluations, all individuals together
};

GeneticResult geneticMtsp(const CostMatrix& costs, const MtspProblem& problem,
                          const GeneticOptions& options = {});

// The TSP as a one-vehicle problem; `initialCost` receives the initial population's best cost.
Tour geneticTsp(const CostMatrix& costs, const TourProblem& problem,
                const GeneticOptions& options = {}, double* initialCost = nullptr);

}  // namespace coinspect::planning
