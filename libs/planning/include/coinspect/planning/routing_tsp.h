// Heuristic TSP / ATSP: construction (nearest neighbour and cheapest insertion, the better one)
// then local search (2-opt and Or-opt) until no move improves or the budget is spent.
//
// Everything is deterministic: candidates are scanned in index order and the budget counts move
// evaluations, never wall time, so the same input always gives the same tour.
#pragma once

#include <cstdint>

#include "coinspect/planning/tour.h"

namespace coinspect::planning {

struct LocalSearchOptions {
  bool twoOpt = true;  // reverse a stretch (asymmetric: the reversed stretch's true cost)
  bool orOpt = true;   // move a stretch of 1..orOptMaxSegment nodes, either way round
  int orOptMaxSegment = 3;
  int64_t maxEvaluations = 0;  // move evaluations allowed; 0 = until a local optimum
  // Iterated local search: this many times, exchange two random adjacent stretches of the best
  // tour (a "double bridge", no reversal, so fit for asymmetric costs; mTSP: of all routes one
  // after the other, then cut into routes again), search again, keep the result if it is
  // better. Escapes the local optima that 2-opt/Or-opt leave on irregular asymmetric costs and
  // that relocate/swap leave under min-max; each kick costs a few sweeps. Seeded.
  int kicks = 0;
  uint64_t seed = 1;
};

struct RoutingStats {
  double constructionCost = 0.0;  // the better construction's cost, before local search
  int64_t evaluations = 0;        // move evaluations spent by the local search
};

// The better of nearest neighbour and cheapest insertion (ties: nearest neighbour).
Tour constructTour(const CostMatrix& costs, const TourProblem& problem);

// Local search from `initial` (a valid tour of `problem`); never returns a costlier tour.
Tour improveTour(const CostMatrix& costs, const TourProblem& problem, const Tour& initial,
                 const LocalSearchOptions& options = {}, RoutingStats* stats = nullptr);

// constructTour then improveTour. Forbidden edges are avoided whenever the search finds a way
// round them; when it cannot, the returned cost is +infinity.
Tour solveTsp(const CostMatrix& costs, const TourProblem& problem,
              const LocalSearchOptions& options = {}, RoutingStats* stats = nullptr);

}  // namespace coinspect::planning
