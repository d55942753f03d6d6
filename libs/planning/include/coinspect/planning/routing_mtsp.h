// Multi-vehicle routing (mTSP): m vehicles, each leaving its own start node, together visit every
// other node once; routes are open paths, or all end at a common depot node.
//
// Construction inserts nodes one at a time where the objective grows least; then local search
// alternates moves between routes (relocate a node, swap two nodes) with 2-opt / Or-opt inside
// each route, until nothing improves or the evaluation budget is spent. Deterministic.
#pragma once

#include <vector>

#include "coinspect/planning/routing_tsp.h"

namespace coinspect::planning {

enum class MtspObjective {
  MinSum,  // total cost of all routes (then makespan on ties)
  MinMax,  // the costliest route, the makespan (then total on ties)
};

struct MtspProblem {
  std::vector<int> starts;  // one distinct start node per vehicle
  int depot = -1;           // node where every route ends, or -1 for open routes
  MtspObjective objective = MtspObjective::MinSum;
};

struct MtspSolution {
  // routes[v]: vehicle v's start, the nodes it visits in order, then the depot if there is one.
  std::vector<std::vector<int>> routes;
  std::vector<double> routeCosts;
  double totalCost = 0.0;
  double makespan = 0.0;
};

// Throws InputError (source "mtsp problem") for no vehicle, a node outside the matrix, repeated
// starts or a depot that is also a start.
void validateMtspProblem(const CostMatrix& costs, const MtspProblem& problem);

// Fills routeCosts, totalCost and makespan from the routes.
void evaluateMtsp(const CostMatrix& costs, MtspSolution& solution);

// True when every node that is neither a start nor the depot is visited exactly once and every
// route starts (and ends) where the problem says.
bool isValidMtsp(const CostMatrix& costs, const MtspProblem& problem, const MtspSolution& solution);

// True when `a` is strictly better than `b` under the objective (with a small tolerance).
bool mtspBetter(MtspObjective objective, const MtspSolution& a, const MtspSolution& b);

MtspSolution constructMtsp(const CostMatrix& costs, const MtspProblem& problem);

// Local search from `initial` (valid for `problem`); never returns a worse solution.
MtspSolution improveMtsp(const CostMatrix& costs, const MtspProblem& problem,
                         const MtspSolution& initial, const LocalSearchOptions& options = {},
                         RoutingStats* stats = nullptr);

MtspSolution solveMtsp(const CostMatrix& costs, const MtspProblem& problem,
                       const LocalSearchOptions& options = {}, RoutingStats* stats = nullptr);

}  // namespace coinspect::planning
