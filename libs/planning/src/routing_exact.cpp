// Held-Karp: best[S][j] = cheapest path from the start through exactly the set S, ending at j.
#include "coinspect/planning/routing_exact.h"

#include <limits>
#include <string>

#include "coinspect/core/error.h"

namespace coinspect::planning {

Tour heldKarp(const CostMatrix& costs, const TourProblem& problem) {
  validateTourProblem(costs, problem);
  const int n = costs.size();
  if (n > kHeldKarpMaxNodes) {
    throw InputError("tour problem", "cost matrix",
                     std::to_string(n) + " nodes is too many for Held-Karp (at most " +
                         std::to_string(kHeldKarpMaxNodes) + ")");
  }
  const int end = problem.kind == TourKind::Closed ? problem.start : problem.end;
  std::vector<int> visit;
  for (int node = 0; node < n; ++node) {
    if (node != problem.start && node != end) visit.push_back(node);
  }
  const int k = static_cast<int>(visit.size());
  const auto closing = [&](int last) { return end >= 0 ? costs(last, end) : 0.0; };

  // A fallback order for when every tour is infeasible; replaced by the optimum otherwise.
  Tour tour;
  tour.order.push_back(problem.start);
  tour.order.insert(tour.order.end(), visit.begin(), visit.end());
  if (problem.kind == TourKind::Open && end >= 0) tour.order.push_back(end);
  if (k == 0) {
    tour.cost = tourCost(costs, tour.order, problem.kind);
    return tour;
  }

  const double inf = std::numeric_limits<double>::infinity();
  const size_t states = size_t{1} << k;
  std::vector<double> best(states * k, inf);
  std::vector<signed char> parent(states * k, -1);
  for (int j = 0; j < k; ++j)
    best[(size_t{1} << j) * k + j] = costs(problem.start, visit[j]);
  for (size_t mask = 1; mask < states; ++mask) {
    for (int j = 0; j < k; ++j) {
      const double here = best[mask * k + j];
      if (!(mask >> j & 1) || here == inf) continue;
      for (int t = 0; t < k; ++t) {
        if (mask >> t & 1) continue;
        const size_t next = (mask | size_t{1} << t) * k + t;
        const double candidate = here + costs(visit[j], visit[t]);
        if (candidate < best[next]) {
          best[next] = candidate;
          parent[next] = static_cast<signed char>(j);
        }
      }
    }
  }

  const size_t full = states - 1;
  int last = -1;
  double bestCost = inf;
  for (int j = 0; j < k; ++j) {
    const double candidate = best[full * k + j] + closing(visit[j]);
    if (candidate < bestCost) {
      bestCost = candidate;
      last = j;
    }
  }
  if (last < 0) {
    tour.cost = inf;
    return tour;
  }
  std::vector<int> reversed;
  size_t mask = full;
  for (int j = last; j >= 0;) {
    reversed.push_back(visit[j]);
    const int previous = parent[mask * k + j];
    mask &= ~(size_t{1} << j);
    j = previous;
  }
  tour.order.assign(1, problem.start);
  tour.order.insert(tour.order.end(), reversed.rbegin(), reversed.rend());
  if (problem.kind == TourKind::Open && end >= 0) tour.order.push_back(end);
  tour.cost = tourCost(costs, tour.order, problem.kind);
  return tour;
}

}  // namespace coinspect::planning
