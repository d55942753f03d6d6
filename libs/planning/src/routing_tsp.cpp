// Single-vehicle tours: a tour is one route of the shared machinery (routing_internal.h).
#include "coinspect/planning/routing_tsp.h"

#include "coinspect/core/error.h"
#include "routing_internal.h"

namespace coinspect::planning {

namespace detail {

RoutingProblem toRoutingProblem(const CostMatrix& costs, const TourProblem& problem) {
  validateTourProblem(costs, problem);
  RoutingProblem routing;
  const int end = problem.kind == TourKind::Closed ? problem.start : problem.end;
  routing.vehicles.push_back({problem.start, end});
  for (int node = 0; node < costs.size(); ++node) {
    if (node != problem.start && node != end) routing.visit.push_back(node);
  }
  return routing;
}

Tour toTour(const CostMatrix& costs, const TourProblem& problem, std::vector<int> route) {
  if (problem.kind == TourKind::Closed) route.pop_back();  // the start again
  Tour tour;
  tour.cost = tourCost(costs, route, problem.kind);
  tour.order = std::move(route);
  return tour;
}

}  // namespace detail

Tour constructTour(const CostMatrix& costs, const TourProblem& problem) {
  const detail::RoutingProblem routing = detail::toRoutingProblem(costs, problem);
  const detail::WorkCosts work(costs);
  std::vector<int> nearest =
      detail::nearestNeighbourRoute(work, routing.vehicles[0], routing.visit);
  std::vector<int> inserted = detail::insertionRoutes(work, routing)[0];
  const bool insertionBetter =
      detail::routeCost(work, inserted) < detail::routeCost(work, nearest) - work.epsilon();
  return detail::toTour(costs, problem, insertionBetter ? std::move(inserted) : std::move(nearest));
}

Tour improveTour(const CostMatrix& costs, const TourProblem& problem, const Tour& initial,
                 const LocalSearchOptions& options, RoutingStats* stats) {
  validateTourProblem(costs, problem);
  if (!isValidTour(costs, problem, initial.order))
    throw InputError("tour", "order", "does not visit every node once from the problem's start");
  const detail::WorkCosts work(costs);
  std::vector<int> route = initial.order;
  if (problem.kind == TourKind::Closed) route.push_back(problem.start);
  detail::Budget budget{options.maxEvaluations, 0};
  const bool fixedEnd = problem.kind == TourKind::Closed || problem.end >= 0;
  detail::iteratedRouteSearch(work, options, budget, route, fixedEnd);
  if (stats) {
    stats->constructionCost = tourCost(costs, initial.order, problem.kind);
    stats->evaluations = budget.used;
  }
  return detail::toTour(costs, problem, std::move(route));
}

Tour solveTsp(const CostMatrix& costs, const TourProblem& problem,
              const LocalSearchOptions& options, RoutingStats* stats) {
  return improveTour(costs, problem, constructTour(costs, problem), options, stats);
}

}  // namespace coinspect::planning
