// mTSP local search: relocate and swap between routes, 2-opt / Or-opt inside each changed route.
//
// Moves between routes are evaluated in O(1) from the few edges they change; the objective
// (total or makespan) is compared lexicographically, so a move that keeps the makespan but
// shortens the total is still progress under MinMax.
#include <algorithm>

#include "routing_internal.h"

namespace coinspect::planning::detail {

namespace {

class InterRouteSearch {
 public:
  InterRouteSearch(const WorkCosts& costs, const RoutingProblem& problem, Budget& budget,
                   Routes& routes)
      : c_(costs),
        problem_(problem),
        budget_(budget),
        routes_(routes),
        m_(static_cast<int>(routes.size())),
        cost_(m_),
        dirty_(m_, 1) {
    for (int r = 0; r < m_; ++r)
      cost_[r] = routeCost(c_, routes_[r]);
  }

  void run(const LocalSearchOptions& options) {
    for (;;) {
      for (int r = 0; r < m_ && !budget_.exhausted(); ++r) {
        if (!dirty_[r]) continue;
        improveRoute(c_, options, budget_, routes_[r], problem_.vehicles[r].end >= 0);
        cost_[r] = routeCost(c_, routes_[r]);
        dirty_[r] = 0;
      }
      if (m_ < 2 || budget_.exhausted()) return;
      bool improved = interRoutePass();
      if (!budget_.exhausted() && tailExchangePass()) improved = true;
      if (!improved) return;
    }
  }

 private:
  int lastMovable(int r) const {
    const int size = static_cast<int>(routes_[r].size());
    return problem_.vehicles[r].end >= 0 ? size - 2 : size - 1;
  }
  // Cost change of the edges around position i of route r if its node became `node`
  // (node == -1: the node is removed).
  double replaceDelta(int r, int i, int node) const {
    const auto& route = routes_[r];
    const int prev = route[i - 1], old = route[i];
    const bool hasNext = i + 1 < static_cast<int>(route.size());
    const int next = hasNext ? route[i + 1] : -1;
    double delta = -c_(prev, old) - (hasNext ? c_(old, next) : 0.0);
    if (node < 0) return delta + (hasNext ? c_(prev, next) : 0.0);
    return delta + c_(prev, node) + (hasNext ? c_(node, next) : 0.0);
  }
  // Cost change of inserting `node` after position k of route r.
  double insertDelta(int r, int k, int node) const {
    const auto& route = routes_[r];
    const int a = route[k];
    if (k + 1 >= static_cast<int>(route.size())) return c_(a, node);
    const int b = route[k + 1];
    return c_(a, node) + c_(node, b) - c_(a, b);
  }
  Score current() const {
    Score score;
    for (double cost : cost_) {
      score.total += cost;
      score.makespan = std::max(score.makespan, cost);
    }
    return score;
  }
  double maxExcept(int a, int b) const {
    double largest = 0.0;
    for (int r = 0; r < m_; ++r) {
      if (r != a && r != b) largest = std::max(largest, cost_[r]);
    }
    return largest;
  }
  void changed(int r) {
    cost_[r] = routeCost(c_, routes_[r]);
    dirty_[r] = 1;
  }

  // One sweep over every node: the first improving relocate or swap involving it is applied.
  bool interRoutePass() {
    bool improved = false;
    for (int a = 0; a < m_; ++a) {
      for (int i = 1; i <= lastMovable(a);) {
        if (budget_.exhausted()) return improved;
        if (tryNode(a, i)) {
          improved = true;  // position i now holds another node: look at it too
        } else {
          ++i;
        }
      }
    }
    return improved;
  }

  // 2-opt*: route a keeps its head up to position i and takes route b's tail after position j,
  // and the other way round. Tails keep their direction, so asymmetric costs need no care.
  bool tailExchangePass() {
    bool improved = false;
    for (int a = 0; a < m_; ++a) {
      for (int b = a + 1; b < m_; ++b) {
        while (!budget_.exhausted() && exchangeTails(a, b))
          improved = true;
      }
    }
    return improved;
  }

  bool exchangeTails(int a, int b) {
    const std::vector<int>&p = routes_[a], &q = routes_[b];
    const std::vector<double> headA = prefixCosts(p), headB = prefixCosts(q);
    const double others = maxExcept(a, b);
    const Score now = current();
    const double eps = c_.epsilon();
    // A tail after position i: empty for i = size - 1 (only with a free end).
    const auto joined = [&](const std::vector<int>& head, const std::vector<double>& headCost,
                            int i, const std::vector<int>& tail,
                            const std::vector<double>& tailPrefix, int j) {
      const int tailSize = static_cast<int>(tail.size());
      if (j + 1 >= tailSize) return headCost[i];
      return headCost[i] + c_(head[i], tail[j + 1]) + tailPrefix.back() - tailPrefix[j + 1];
    };
    for (int i = 0; i <= lastMovable(a); ++i) {
      for (int j = 0; j <= lastMovable(b); ++j) {
        if (budget_.exhausted()) return false;
        ++budget_.used;
        const double newA = joined(p, headA, i, q, headB, j);
        const double newB = joined(q, headB, j, p, headA, i);
        const Score exchanged{std::max({others, newA, newB}),
                              now.total - cost_[a] - cost_[b] + newA + newB};
        if (better(problem_.objective, exchanged, now, eps)) {
          std::vector<int> first(p.begin(), p.begin() + i + 1);
          first.insert(first.end(), q.begin() + j + 1, q.end());
          std::vector<int> second(q.begin(), q.begin() + j + 1);
          second.insert(second.end(), p.begin() + i + 1, p.end());
          routes_[a].swap(first);
          routes_[b].swap(second);
          changed(a);
          changed(b);
          return true;
        }
      }
    }
    return false;
  }

  std::vector<double> prefixCosts(const std::vector<int>& route) const {
    std::vector<double> prefix(route.size(), 0.0);
    for (size_t t = 1; t < route.size(); ++t)
      prefix[t] = prefix[t - 1] + c_(route[t - 1], route[t]);
    return prefix;
  }

  bool tryNode(int a, int i) {
    const MtspObjective objective = problem_.objective;
    const double eps = c_.epsilon();
    const Score now = current();
    const int u = routes_[a][i];
    const double removal = replaceDelta(a, i, -1);
    for (int b = 0; b < m_; ++b) {
      if (b == a) continue;
      const double others = maxExcept(a, b);
      const double newA = cost_[a] + removal;
      for (int k = 0; k <= lastMovable(b); ++k) {
        if (budget_.exhausted()) return false;
        ++budget_.used;
        const double insertion = insertDelta(b, k, u);
        const double newB = cost_[b] + insertion;
        const Score moved{std::max({others, newA, newB}), now.total + removal + insertion};
        if (better(objective, moved, now, eps)) {
          routes_[a].erase(routes_[a].begin() + i);
          routes_[b].insert(routes_[b].begin() + k + 1, u);
          changed(a);
          changed(b);
          return true;
        }
      }
      if (b < a) continue;  // swaps are symmetric: each pair of routes once
      for (int j = 1; j <= lastMovable(b); ++j) {
        if (budget_.exhausted()) return false;
        ++budget_.used;
        const int w = routes_[b][j];
        const double deltaA = replaceDelta(a, i, w);
        const double deltaB = replaceDelta(b, j, u);
        const double swappedA = cost_[a] + deltaA, swappedB = cost_[b] + deltaB;
        const Score swapped{std::max({others, swappedA, swappedB}), now.total + deltaA + deltaB};
        if (better(objective, swapped, now, eps)) {
          std::swap(routes_[a][i], routes_[b][j]);
          changed(a);
          changed(b);
          return true;
        }
      }
    }
    return false;
  }

  const WorkCosts& c_;
  const RoutingProblem& problem_;
  Budget& budget_;
  Routes& routes_;
  int m_;
  std::vector<double> cost_;
  std::vector<char> dirty_;  // routes changed since their last intra-route search
};

}  // namespace

void improveRoutes(const WorkCosts& costs, const RoutingProblem& problem,
                   const LocalSearchOptions& options, Budget& budget, Routes& routes) {
  InterRouteSearch(costs, problem, budget, routes).run(options);
}

void iteratedRoutesSearch(const WorkCosts& costs, const RoutingProblem& problem,
                          const LocalSearchOptions& options, Budget& budget, Routes& routes) {
  improveRoutes(costs, problem, options, budget, routes);
  const int visits = static_cast<int>(problem.visit.size());
  if (options.kicks <= 0 || visits < 4) return;
  Rng rng(options.seed);
  Score best = scoreRoutes(costs, routes);
  for (int kick = 0; kick < options.kicks && !budget.exhausted(); ++kick) {
    std::vector<int> giant = giantTour(problem, routes);
    doubleBridge(rng, giant, 0, visits);
    Routes trial = splitGiantTour(costs, problem, giant);
    improveRoutes(costs, problem, options, budget, trial);
    const Score score = scoreRoutes(costs, trial);
    if (better(problem.objective, score, best, costs.epsilon())) {
      best = score;
      routes.swap(trial);
    }
  }
}

}  // namespace coinspect::planning::detail
