// WorkCosts, scores and conversions shared by the routing solvers.
#include <algorithm>
#include <cmath>
#include <string>

#include "coinspect/core/error.h"
#include "routing_internal.h"

namespace coinspect::planning::detail {

WorkCosts::WorkCosts(const CostMatrix& costs) : n_(costs.size()), c_(costs.rowMajor()) {
  double largest = 0.0;
  for (double cost : c_) {
    if (std::isfinite(cost)) largest = std::max(largest, cost);
  }
  // A solution has at most 2n edges (n nodes, m <= n routes), each <= largest: any penalty above
  // 2n * largest ranks one forbidden edge below every feasible solution.
  const double edgesBound = 2.0 * n_ + 2.0;
  const double penalty = edgesBound * largest + 1.0;
  if (!std::isfinite(penalty * edgesBound)) {
    throw InputError("cost matrix", "largest finite cost",
                     std::to_string(largest) + " is too large to rank forbidden edges");
  }
  for (int i = 0; i < n_; ++i) {
    for (int j = 0; j < n_; ++j) {
      double& cost = c_[static_cast<size_t>(i) * n_ + j];
      if (i == j) {
        cost = 0.0;
      } else if (!std::isfinite(cost)) {
        cost = penalty;
      }
    }
  }
  epsilon_ = 1e-9 * penalty / edgesBound;
}

bool better(MtspObjective objective, const Score& a, const Score& b, double epsilon) {
  const double first =
      objective == MtspObjective::MinMax ? a.makespan - b.makespan : a.total - b.total;
  if (first < -epsilon) return true;
  if (first > epsilon) return false;
  const double second =
      objective == MtspObjective::MinMax ? a.total - b.total : a.makespan - b.makespan;
  return second < -epsilon;
}

double routeCost(const WorkCosts& costs, const std::vector<int>& route) {
  double total = 0.0;
  for (size_t i = 1; i < route.size(); ++i)
    total += costs(route[i - 1], route[i]);
  return total;
}

Score scoreRoutes(const WorkCosts& costs, const Routes& routes) {
  Score score;
  for (const auto& route : routes) {
    const double cost = routeCost(costs, route);
    score.total += cost;
    score.makespan = std::max(score.makespan, cost);
  }
  return score;
}

std::vector<int> emptyRoute(const RouteEnds& ends) {
  std::vector<int> route{ends.start};
  if (ends.end >= 0) route.push_back(ends.end);
  return route;
}

std::vector<int> giantTour(const RoutingProblem& problem, const Routes& routes) {
  std::vector<int> giant;
  giant.reserve(problem.visit.size());
  for (size_t v = 0; v < routes.size(); ++v) {
    const auto& route = routes[v];
    const size_t stop = route.size() - (problem.vehicles[v].end >= 0 ? 1 : 0);
    giant.insert(giant.end(), route.begin() + 1, route.begin() + stop);
  }
  return giant;
}

RoutingProblem toRoutingProblem(const CostMatrix& costs, const MtspProblem& problem) {
  validateMtspProblem(costs, problem);
  RoutingProblem routing;
  routing.objective = problem.objective;
  std::vector<char> fixed(costs.size(), 0);
  for (int start : problem.starts) {
    routing.vehicles.push_back({start, problem.depot});
    fixed[start] = 1;
  }
  if (problem.depot >= 0) fixed[problem.depot] = 1;
  for (int node = 0; node < costs.size(); ++node) {
    if (!fixed[node]) routing.visit.push_back(node);
  }
  return routing;
}

MtspSolution toSolution(const CostMatrix& costs, Routes routes) {
  MtspSolution solution;
  solution.routes = std::move(routes);
  evaluateMtsp(costs, solution);
  return solution;
}

}  // namespace coinspect::planning::detail
