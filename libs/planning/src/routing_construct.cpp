// Construction heuristics: nearest neighbour (one route) and cheapest insertion (any number of
// routes, objective-aware).
#include <algorithm>
#include <limits>

#include "routing_internal.h"

namespace coinspect::planning::detail {

std::vector<int> nearestNeighbourRoute(const WorkCosts& costs, const RouteEnds& ends,
                                       const std::vector<int>& visit) {
  std::vector<int> route{ends.start};
  route.reserve(visit.size() + 2);
  std::vector<char> used(visit.size(), 0);
  int current = ends.start;
  for (size_t step = 0; step < visit.size(); ++step) {
    size_t chosen = visit.size();
    double chosenCost = std::numeric_limits<double>::infinity();
    for (size_t i = 0; i < visit.size(); ++i) {
      if (!used[i] && costs(current, visit[i]) < chosenCost) {
        chosen = i;
        chosenCost = costs(current, visit[i]);
      }
    }
    used[chosen] = 1;
    current = visit[chosen];
    route.push_back(current);
  }
  if (ends.end >= 0) route.push_back(ends.end);
  return route;
}

namespace {

// Where a node would go in one route: after node `after`, for `delta` more cost.
struct Insertion {
  double delta = std::numeric_limits<double>::infinity();
  int after = -1;
};

class InsertionBuilder {
 public:
  InsertionBuilder(const WorkCosts& costs, const RoutingProblem& problem)
      : c_(costs),
        problem_(problem),
        m_(static_cast<int>(problem.vehicles.size())),
        position_(costs.size(), -1),
        routeCost_(m_, 0.0),
        best_(problem.visit.size() * m_) {
    for (int r = 0; r < m_; ++r) {
      routes_.push_back(emptyRoute(problem.vehicles[r]));
      position_[problem.vehicles[r].start] = 0;
      routeCost_[r] = routeCost(c_, routes_[r]);
    }
    for (size_t u = 0; u < problem.visit.size(); ++u) {
      for (int r = 0; r < m_; ++r)
        best(u, r) = scan(problem.visit[u], r);
    }
  }

  Routes build() {
    std::vector<char> remaining(problem_.visit.size(), 1);
    for (size_t step = 0; step < problem_.visit.size(); ++step) {
      size_t chosenU = 0;
      int chosenR = -1;
      double chosenKey = 0.0, chosenDelta = 0.0;
      const double makespan = *std::max_element(routeCost_.begin(), routeCost_.end());
      for (size_t u = 0; u < problem_.visit.size(); ++u) {
        if (!remaining[u]) continue;
        for (int r = 0; r < m_; ++r) {
          const double delta = best(u, r).delta;
          const double key = problem_.objective == MtspObjective::MinMax
                                 ? std::max(makespan, routeCost_[r] + delta)
                                 : delta;
          if (chosenR < 0 || key < chosenKey || (key == chosenKey && delta < chosenDelta)) {
            chosenU = u;
            chosenR = r;
            chosenKey = key;
            chosenDelta = delta;
          }
        }
      }
      remaining[chosenU] = 0;
      insert(problem_.visit[chosenU], chosenR, best(chosenU, chosenR), remaining);
    }
    return std::move(routes_);
  }

 private:
  Insertion& best(size_t u, int r) { return best_[u * m_ + r]; }
  int lastPlace(int r) const {
    const int size = static_cast<int>(routes_[r].size());
    return problem_.vehicles[r].end >= 0 ? size - 2 : size - 1;
  }
  double cost(int r, int k, int node) const {
    const auto& route = routes_[r];
    const int a = route[k];
    if (k + 1 >= static_cast<int>(route.size())) return c_(a, node);
    const int b = route[k + 1];
    return c_(a, node) + c_(node, b) - c_(a, b);
  }
  Insertion scan(int node, int r) const {
    Insertion found;
    for (int k = 0; k <= lastPlace(r); ++k) {
      const double delta = cost(r, k, node);
      if (delta < found.delta) found = {delta, routes_[r][k]};
    }
    return found;
  }

  void insert(int node, int r, Insertion where, const std::vector<char>& remaining) {
    auto& route = routes_[r];
    const int k = position_[where.after];
    route.insert(route.begin() + k + 1, node);
    for (int i = k + 1; i <= lastPlace(r); ++i)
      position_[route[i]] = i;
    routeCost_[r] += where.delta;
    // Only route r changed: its place after `where.after` now lies before `node`, and there is
    // a new place after `node`.
    for (size_t u = 0; u < problem_.visit.size(); ++u) {
      if (!remaining[u]) continue;
      Insertion& entry = best(u, r);
      const int w = problem_.visit[u];
      if (entry.after == where.after) {
        entry = scan(w, r);
        continue;
      }
      const double beforeNode = cost(r, k, w);
      if (beforeNode < entry.delta) entry = {beforeNode, where.after};
      const double afterNode = cost(r, k + 1, w);
      if (afterNode < entry.delta) entry = {afterNode, node};
    }
  }

  const WorkCosts& c_;
  const RoutingProblem& problem_;
  int m_;
  Routes routes_;
  std::vector<int> position_;  // index of a node in its route (starts: 0)
  std::vector<double> routeCost_;
  std::vector<Insertion> best_;  // per (node to visit, route): its cheapest place
};

}  // namespace

Routes insertionRoutes(const WorkCosts& costs, const RoutingProblem& problem) {
  return InsertionBuilder(costs, problem).build();
}

}  // namespace coinspect::planning::detail
