// Shared machinery of the routing solvers (not a public header).
//
// Every solver works on routes: a route is a path p[0..L-1] whose first node is its vehicle's
// start and, when the route has a fixed end (a depot, or the start again for a closed tour), whose
// last node is that end; the nodes in between are free to move. A single TSP tour is one route,
// an mTSP solution one route per vehicle.
#pragma once

#include <cstdint>
#include <vector>

#include "coinspect/core/random.h"
#include "coinspect/planning/routing_cost_matrix.h"
#include "coinspect/planning/routing_mtsp.h"
#include "coinspect/planning/routing_tsp.h"

namespace coinspect::planning::detail {

// The costs the searches compare: forbidden edges become a penalty larger than any feasible
// solution's total (so a solution with fewer forbidden edges always wins and sums stay finite
// for the O(1) move evaluations), the diagonal is zero.
class WorkCosts {
 public:
  explicit WorkCosts(const CostMatrix& costs);
  int size() const { return n_; }
  double operator()(int from, int to) const { return c_[static_cast<size_t>(from) * n_ + to]; }
  // Improvements smaller than this are rounding noise, not progress.
  double epsilon() const { return epsilon_; }

 private:
  int n_ = 0;
  std::vector<double> c_;
  double epsilon_ = 0.0;
};

// Counts move evaluations against an optional limit (0 = none).
struct Budget {
  int64_t limit = 0;
  int64_t used = 0;
  bool exhausted() const { return limit > 0 && used >= limit; }
};

struct RouteEnds {
  int start = 0;
  int end = -1;  // -1: free end; may equal start (a closed tour)
};

struct RoutingProblem {
  std::vector<RouteEnds> vehicles;
  std::vector<int> visit;  // the nodes to distribute over the routes, ascending
  MtspObjective objective = MtspObjective::MinSum;
};

using Routes = std::vector<std::vector<int>>;

// Objective value of a set of routes.
struct Score {
  double makespan = 0.0;
  double total = 0.0;
};
bool better(MtspObjective objective, const Score& a, const Score& b, double epsilon);

double routeCost(const WorkCosts& costs, const std::vector<int>& route);
Score scoreRoutes(const WorkCosts& costs, const Routes& routes);
// An empty route: its start, then its end if fixed.
std::vector<int> emptyRoute(const RouteEnds& ends);

// One route through `visit` (any order of the nodes in it).
std::vector<int> nearestNeighbourRoute(const WorkCosts& costs, const RouteEnds& ends,
                                       const std::vector<int>& visit);
// Cheapest insertion into all routes at once. MinSum inserts where the total grows least;
// MinMax where the makespan grows least, then the total.
Routes insertionRoutes(const WorkCosts& costs, const RoutingProblem& problem);

// 2-opt and Or-opt inside one route until no move improves or the budget is spent. Returns true
// when the route changed (it is then strictly cheaper).
bool improveRoute(const WorkCosts& costs, const LocalSearchOptions& options, Budget& budget,
                  std::vector<int>& route, bool fixedEnd);

// improveRoute, then options.kicks double-bridge kicks each followed by improveRoute, keeping
// the best route (iterated local search).
bool iteratedRouteSearch(const WorkCosts& costs, const LocalSearchOptions& options, Budget& budget,
                         std::vector<int>& route, bool fixedEnd);

// Intra-route search on every route alternated with relocate and swap moves between routes.
void improveRoutes(const WorkCosts& costs, const RoutingProblem& problem,
                   const LocalSearchOptions& options, Budget& budget, Routes& routes);

// improveRoutes, then options.kicks kicks (a double bridge on the giant tour of the best routes,
// split again, improveRoutes), keeping the best routes (iterated local search).
void iteratedRoutesSearch(const WorkCosts& costs, const RoutingProblem& problem,
                          const LocalSearchOptions& options, Budget& budget, Routes& routes);

// A double bridge: three random cuts a < b < c in [first + 1, stop), then A B C D -> A C B D for
// the stretches [first, a), [a, b), [b, c), [c, stop). Needs stop - first >= 4.
void doubleBridge(Rng& rng, std::vector<int>& sequence, int first, int stop);

// The visited nodes of all routes, vehicle after vehicle.
std::vector<int> giantTour(const RoutingProblem& problem, const Routes& routes);
// The best cut of a giant tour into consecutive routes of vehicles 0, 1, ... m-1, in that order
// (exact for the makespan or the total; ties of the other term are settled greedily).
Routes splitGiantTour(const WorkCosts& costs, const RoutingProblem& problem,
                      const std::vector<int>& giant);

// A tour as a one-route problem, and back.
RoutingProblem toRoutingProblem(const CostMatrix& costs, const TourProblem& problem);
Tour toTour(const CostMatrix& costs, const TourProblem& problem, std::vector<int> route);

// The mTSP as routes, and back.
RoutingProblem toRoutingProblem(const CostMatrix& costs, const MtspProblem& problem);
MtspSolution toSolution(const CostMatrix& costs, Routes routes);

}  // namespace coinspect::planning::detail
