// Giant tours: all visited nodes, vehicle after vehicle, and their best cut back into routes.
#include <algorithm>

#include "routing_internal.h"

namespace coinspect::planning::detail {

Routes splitGiantTour(const WorkCosts& costs, const RoutingProblem& problem,
                      const std::vector<int>& giant) {
  const int m = static_cast<int>(problem.vehicles.size());
  const int k = static_cast<int>(giant.size());
  std::vector<double> along(std::max(k, 1), 0.0);  // along[t]: cost of giant[0] -> ... giant[t]
  for (int t = 1; t < k; ++t)
    along[t] = along[t - 1] + costs(giant[t - 1], giant[t]);
  // Cost of vehicle v's route through giant[i..j).
  const auto chunk = [&](int v, int i, int j) {
    const RouteEnds& ends = problem.vehicles[v];
    if (i == j) return ends.end >= 0 ? costs(ends.start, ends.end) : 0.0;
    double cost = costs(ends.start, giant[i]) + along[j - 1] - along[i];
    if (ends.end >= 0) cost += costs(giant[j - 1], ends.end);
    return cost;
  };

  // best[v][j]: routes of vehicles 0..v covering giant[0..j); cut[v][j]: where v's route begins.
  std::vector<std::vector<Score>> best(m, std::vector<Score>(k + 1));
  std::vector<std::vector<int>> cut(m, std::vector<int>(k + 1, 0));
  for (int j = 0; j <= k; ++j) {
    const double cost = chunk(0, 0, j);
    best[0][j] = {cost, cost};
  }
  for (int v = 1; v < m; ++v) {
    for (int j = 0; j <= k; ++j) {
      for (int i = 0; i <= j; ++i) {
        const double cost = chunk(v, i, j);
        const Score candidate{std::max(best[v - 1][i].makespan, cost), best[v - 1][i].total + cost};
        if (i == 0 || better(problem.objective, candidate, best[v][j], costs.epsilon())) {
          best[v][j] = candidate;
          cut[v][j] = i;
        }
      }
    }
  }

  Routes routes(m);
  int j = k;
  for (int v = m - 1; v >= 0; --v) {
    const int i = v > 0 ? cut[v][j] : 0;
    routes[v].push_back(problem.vehicles[v].start);
    routes[v].insert(routes[v].end(), giant.begin() + i, giant.begin() + j);
    if (problem.vehicles[v].end >= 0) routes[v].push_back(problem.vehicles[v].end);
    j = i;
  }
  return routes;
}

}  // namespace coinspect::planning::detail
