// 2-opt and Or-opt inside one route, in O(1) per move evaluation for asymmetric costs too.
//
// Prefix sums of the route's edges in both directions give the cost of any stretch and of the
// same stretch walked backwards, so reversing a stretch (2-opt) or re-inserting it the other way
// round (Or-opt) is evaluated exactly without walking it.
#include <algorithm>

#include "coinspect/core/random.h"

#include "routing_internal.h"

namespace coinspect::planning::detail {

namespace {

class RouteSearch {
 public:
  RouteSearch(const WorkCosts& costs, Budget& budget, std::vector<int>& route, bool fixedEnd)
      : c_(costs), budget_(budget), p_(route), fixedEnd_(fixedEnd) {
    updatePrefixSums();
  }

  // One sweep over all stretch reversals p[i..j], applying each improving one at once.
  bool twoOptPass() {
    bool improved = false;
    const int size = length();
    const int last = lastMovable();
    const double eps = c_.epsilon();
    for (int i = 1; i < last; ++i) {
      for (int j = i + 1; j <= last; ++j) {
        if (budget_.exhausted()) return improved;
        ++budget_.used;
        const int before = p_[i - 1];
        double delta = c_(before, p_[j]) - c_(before, p_[i]) + (backward_[j] - backward_[i]) -
                       (forward_[j] - forward_[i]);
        if (j + 1 < size) delta += c_(p_[i], p_[j + 1]) - c_(p_[j], p_[j + 1]);
        if (delta < -eps) {
          std::reverse(p_.begin() + i, p_.begin() + j + 1);
          updatePrefixSums();
          improved = true;
        }
      }
    }
    return improved;
  }

  // One sweep moving every stretch of 1..maxSegment nodes to every other place, both ways round.
  bool orOptPass(int maxSegment) {
    bool improved = false;
    const double eps = c_.epsilon();
    for (int len = 1; len <= maxSegment; ++len) {
      for (int i = 1; i + len - 1 <= lastMovable(); ++i) {
        if (budget_.exhausted()) return improved;
        if (moveSegment(i, i + len - 1, eps)) improved = true;
      }
    }
    return improved;
  }

 private:
  int length() const { return static_cast<int>(p_.size()); }
  int lastMovable() const { return fixedEnd_ ? length() - 2 : length() - 1; }

  // Tries p[first..last] after every node k outside it; applies the first improving place.
  bool moveSegment(int first, int last, double eps) {
    const int size = length();
    const int prev = p_[first - 1];
    const bool hasNext = last + 1 < size;
    const double removed =
        c_(prev, p_[first]) + (hasNext ? c_(p_[last], p_[last + 1]) - c_(prev, p_[last + 1]) : 0.0);
    const double reversalChange =
        (backward_[last] - backward_[first]) - (forward_[last] - forward_[first]);
    const int lastPlace = fixedEnd_ ? size - 2 : size - 1;
    for (int k = 0; k <= lastPlace; ++k) {
      if (k >= first - 1 && k <= last) continue;  // the stretch's own place or inside it
      if (budget_.exhausted()) return false;
      ++budget_.used;
      const int a = p_[k];
      const bool hasB = k + 1 < size;
      const int b = hasB ? p_[k + 1] : -1;
      const double opened = hasB ? -c_(a, b) : 0.0;
      const double forwardAdded = c_(a, p_[first]) + (hasB ? c_(p_[last], b) : 0.0) + opened;
      if (forwardAdded - removed < -eps) {
        apply(first, last, k, false);
        return true;
      }
      if (last == first) continue;
      const double reversedAdded =
          c_(a, p_[last]) + (hasB ? c_(p_[first], b) : 0.0) + opened + reversalChange;
      if (reversedAdded - removed < -eps) {
        apply(first, last, k, true);
        return true;
      }
    }
    return false;
  }

  void apply(int first, int last, int after, bool reversed) {
    std::vector<int> segment(p_.begin() + first, p_.begin() + last + 1);
    if (reversed) std::reverse(segment.begin(), segment.end());
    p_.erase(p_.begin() + first, p_.begin() + last + 1);
    const int place = after < first ? after : after - (last - first + 1);
    p_.insert(p_.begin() + place + 1, segment.begin(), segment.end());
    updatePrefixSums();
  }

  void updatePrefixSums() {
    const int size = length();
    forward_.assign(size, 0.0);
    backward_.assign(size, 0.0);
    for (int t = 1; t < size; ++t) {
      forward_[t] = forward_[t - 1] + c_(p_[t - 1], p_[t]);
      backward_[t] = backward_[t - 1] + c_(p_[t], p_[t - 1]);
    }
  }

  const WorkCosts& c_;
  Budget& budget_;
  std::vector<int>& p_;
  bool fixedEnd_;
  std::vector<double> forward_;   // forward_[t]: cost of p[0] -> ... -> p[t]
  std::vector<double> backward_;  // backward_[t]: cost of p[t] -> ... -> p[0]
};

}  // namespace

bool improveRoute(const WorkCosts& costs, const LocalSearchOptions& options, Budget& budget,
                  std::vector<int>& route, bool fixedEnd) {
  RouteSearch search(costs, budget, route, fixedEnd);
  bool changed = false;
  bool again = true;
  while (again && !budget.exhausted()) {
    again = false;
    if (options.twoOpt) {
      while (!budget.exhausted() && search.twoOptPass())
        changed = true;
    }
    if (options.orOpt && options.orOptMaxSegment > 0 && !budget.exhausted() &&
        search.orOptPass(options.orOptMaxSegment)) {
      changed = true;
      again = true;
    }
  }
  return changed;
}

void doubleBridge(Rng& rng, std::vector<int>& sequence, int first, int stop) {
  int cuts[3];
  do {
    for (int& cut : cuts)
      cut = first + 1 + static_cast<int>(rng.below(stop - first - 1));
    std::sort(cuts, cuts + 3);
  } while (cuts[0] == cuts[1] || cuts[1] == cuts[2]);
  std::rotate(sequence.begin() + cuts[0], sequence.begin() + cuts[1], sequence.begin() + cuts[2]);
}

bool iteratedRouteSearch(const WorkCosts& costs, const LocalSearchOptions& options, Budget& budget,
                         std::vector<int>& route, bool fixedEnd) {
  const double before = routeCost(costs, route);
  improveRoute(costs, options, budget, route, fixedEnd);
  const int first = 1;
  const int stop = static_cast<int>(route.size()) - (fixedEnd ? 1 : 0);  // past the last movable
  if (stop - first >= 4 && options.kicks > 0) {
    Rng rng(options.seed);
    double bestCost = routeCost(costs, route);
    std::vector<int> trial;
    for (int kick = 0; kick < options.kicks && !budget.exhausted(); ++kick) {
      trial = route;
      doubleBridge(rng, trial, first, stop);
      improveRoute(costs, options, budget, trial, fixedEnd);
      const double cost = routeCost(costs, trial);
      if (cost < bestCost - costs.epsilon()) {
        bestCost = cost;
        route.swap(trial);
      }
    }
  }
  return routeCost(costs, route) < before - costs.epsilon();
}

}  // namespace coinspect::planning::detail
