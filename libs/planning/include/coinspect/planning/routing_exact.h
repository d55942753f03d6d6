// Exact TSP / ATSP by Held-Karp dynamic programming: O(2^n n^2) time, for small instances and as
// the test oracle of the heuristics.
#pragma once

#include "coinspect/planning/tour.h"

namespace coinspect::planning {

inline constexpr int kHeldKarpMaxNodes = 16;

// The optimal tour of `problem` (open or closed, any costs). When no tour avoids the forbidden
// edges, the cost is +infinity and the order is still a valid visiting order. Throws InputError
// for more than kHeldKarpMaxNodes nodes.
Tour heldKarp(const CostMatrix& costs, const TourProblem& problem);

}  // namespace coinspect::planning
