// mTSP: validation, evaluation, construction and the public entry points.
#include "coinspect/planning/routing_mtsp.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "coinspect/core/error.h"
#include "routing_internal.h"

namespace coinspect::planning {

void validateMtspProblem(const CostMatrix& costs, const MtspProblem& problem) {
  const char* const source = "mtsp problem";
  const int n = costs.size();
  if (problem.starts.empty()) throw InputError(source, "starts", "no vehicle");
  std::vector<char> used(n, 0);
  for (size_t v = 0; v < problem.starts.size(); ++v) {
    const int start = problem.starts[v];
    const std::string where = "starts[" + std::to_string(v) + "]";
    if (start < 0 || start >= n) {
      throw InputError(
          source, where,
          "node " + std::to_string(start) + " is not in [0, " + std::to_string(n) + ")");
    }
    if (used[start])
      throw InputError(source, where, "node " + std::to_string(start) + " starts two vehicles");
    used[start] = 1;
  }
  if (problem.depot == -1) return;
  if (problem.depot < 0 || problem.depot >= n) {
    throw InputError(source, "depot",
                     "node " + std::to_string(problem.depot) + " is not in [0, " +
                         std::to_string(n) + ") (use -1 for open routes)");
  }
  if (used[problem.depot]) {
    throw InputError(source, "depot",
                     "node " + std::to_string(problem.depot) +
                         " is also a start (give each vehicle's start its own node)");
  }
}

void evaluateMtsp(const CostMatrix& costs, MtspSolution& solution) {
  solution.routeCosts.clear();
  solution.totalCost = 0.0;
  solution.makespan = 0.0;
  for (const auto& route : solution.routes) {
    const double cost = tourCost(costs, route, TourKind::Open);
    solution.routeCosts.push_back(cost);
    solution.totalCost += cost;
    solution.makespan = std::max(solution.makespan, cost);
  }
}

bool isValidMtsp(const CostMatrix& costs, const MtspProblem& problem,
                 const MtspSolution& solution) {
  if (solution.routes.size() != problem.starts.size()) return false;
  const int n = costs.size();
  // 0: must be visited, 1: visited, 2: a start or the depot (never visited in between).
  std::vector<char> state(n, 0);
  for (int start : problem.starts)
    state[start] = 2;
  if (problem.depot >= 0) state[problem.depot] = 2;
  for (size_t v = 0; v < solution.routes.size(); ++v) {
    const auto& route = solution.routes[v];
    const size_t fixedEnd = problem.depot >= 0 ? 1 : 0;
    if (route.size() < 1 + fixedEnd || route.front() != problem.starts[v]) return false;
    if (fixedEnd && route.back() != problem.depot) return false;
    for (size_t i = 1; i + fixedEnd < route.size(); ++i) {
      const int node = route[i];
      if (node < 0 || node >= n || state[node] != 0) return false;
      state[node] = 1;
    }
  }
  return std::find(state.begin(), state.end(), 0) == state.end();
}

bool mtspBetter(MtspObjective objective, const MtspSolution& a, const MtspSolution& b) {
  const auto compare = [](double x, double y) {
    const double tolerance = 1e-9 * std::max(1.0, std::abs(y));
    return x < y - tolerance ? -1 : (x > y + tolerance ? 1 : 0);
  };
  const bool minMax = objective == MtspObjective::MinMax;
  const int first = minMax ? compare(a.makespan, b.makespan) : compare(a.totalCost, b.totalCost);
  if (first != 0) return first < 0;
  return (minMax ? compare(a.totalCost, b.totalCost) : compare(a.makespan, b.makespan)) < 0;
}

MtspSolution constructMtsp(const CostMatrix& costs, const MtspProblem& problem) {
  const detail::RoutingProblem routing = detail::toRoutingProblem(costs, problem);
  const detail::WorkCosts work(costs);
  return detail::toSolution(costs, detail::insertionRoutes(work, routing));
}

MtspSolution improveMtsp(const CostMatrix& costs, const MtspProblem& problem,
                         const MtspSolution& initial, const LocalSearchOptions& options,
                         RoutingStats* stats) {
  const detail::RoutingProblem routing = detail::toRoutingProblem(costs, problem);
  if (!isValidMtsp(costs, problem, initial)) {
    throw InputError("mtsp solution", "routes",
                     "do not visit every node once from the vehicles' starts");
  }
  const detail::WorkCosts work(costs);
  detail::Routes routes = initial.routes;
  detail::Budget budget{options.maxEvaluations, 0};
  detail::iteratedRoutesSearch(work, routing, options, budget, routes);
  MtspSolution improved = detail::toSolution(costs, std::move(routes));
  if (stats) {
    MtspSolution start = initial;
    evaluateMtsp(costs, start);
    stats->constructionCost =
        problem.objective == MtspObjective::MinMax ? start.makespan : start.totalCost;
    stats->evaluations = budget.used;
  }
  return improved;
}

MtspSolution solveMtsp(const CostMatrix& costs, const MtspProblem& problem,
                       const LocalSearchOptions& options, RoutingStats* stats) {
  return improveMtsp(costs, problem, constructMtsp(costs, problem), options, stats);
}

}  // namespace coinspect::planning
