#include <string>
#include <vector>

#include "coinspect/core/error.h"
#include "coinspect/planning/tour.h"

namespace coinspect::planning {

double tourCost(const CostMatrix& costs, const std::vector<int>& order, TourKind kind) {
  double total = 0.0;
  for (size_t i = 1; i < order.size(); ++i)
    total += costs(order[i - 1], order[i]);
  if (kind == TourKind::Closed && order.size() > 1) total += costs(order.back(), order.front());
  return total;
}

void validateTourProblem(const CostMatrix& costs, const TourProblem& problem) {
  const char* const source = "tour problem";
  const int n = costs.size();
  if (n == 0) throw InputError(source, "cost matrix", "has no node");
  if (problem.start < 0 || problem.start >= n) {
    throw InputError(
        source, "start",
        "node " + std::to_string(problem.start) + " is not in [0, " + std::to_string(n) + ")");
  }
  if (problem.end == -1) return;
  if (problem.kind == TourKind::Closed)
    throw InputError(source, "end", "a closed tour ends at its start; give no end");
  if (problem.end < 0 || problem.end >= n) {
    throw InputError(source, "end",
                     "node " + std::to_string(problem.end) + " is not in [0, " + std::to_string(n) +
                         ") (use -1 for a free end)");
  }
  if (problem.end == problem.start)
    throw InputError(source, "end", "equals the start; use a closed tour");
}

bool isValidTour(const CostMatrix& costs, const TourProblem& problem,
                 const std::vector<int>& order) {
  const int n = costs.size();
  if (static_cast<int>(order.size()) != n || n == 0) return false;
  std::vector<char> seen(n, 0);
  for (int node : order) {
    if (node < 0 || node >= n || seen[node]) return false;
    seen[node] = 1;
  }
  if (order.front() != problem.start) return false;
  return problem.end < 0 || order.back() == problem.end;
}

}  // namespace coinspect::planning
