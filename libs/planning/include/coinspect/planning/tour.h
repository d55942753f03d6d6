// A single-vehicle tour over every node of a cost matrix: the problem (where it starts and how it
// ends) and the answer (the visiting order and its cost).
#pragma once

#include <vector>

#include "coinspect/planning/routing_cost_matrix.h"

namespace coinspect::planning {

enum class TourKind {
  Closed,  // returns to its start node (the classic TSP)
  Open,    // starts at `start`, ends at `end` if one is given, anywhere otherwise
};

struct TourProblem {
  TourKind kind = TourKind::Closed;
  int start = 0;
  int end = -1;  // Open only: a fixed last node (!= start), or -1 for a free end
};

struct Tour {
  // Every node exactly once, in visiting order, order[0] == start (a closed tour does not repeat
  // it at the end; an open tour with a fixed end has it last).
  std::vector<int> order;
  double cost = 0.0;  // +infinity when the tour uses a forbidden edge
};

// Cost of visiting `order` (closed: including the edge back to order[0]).
double tourCost(const CostMatrix& costs, const std::vector<int>& order, TourKind kind);

// Throws InputError (source "tour problem") when start or end is not a node of `costs`, or an end
// is given for a closed tour or equals the start.
void validateTourProblem(const CostMatrix& costs, const TourProblem& problem);

// True when `order` visits every node exactly once and respects the problem's start and end.
bool isValidTour(const CostMatrix& costs, const TourProblem& problem,
                 const std::vector<int>& order);

}  // namespace coinspect::planning
