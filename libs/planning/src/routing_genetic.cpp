// Memetic GA over giant tours (see routing_genetic.h).
#include "coinspect/planning/routing_genetic.h"

#include <algorithm>
#include <string>

#include "coinspect/core/error.h"
#include "coinspect/core/random.h"
#include "routing_internal.h"

namespace coinspect::planning {

namespace {

void validateOptions(const GeneticOptions& options) {
  const char* const source = "genetic options";
  if (options.population < 1)
    throw InputError(source, "population", std::to_string(options.population) + " is below 1");
  if (options.generations < 0)
    throw InputError(source, "generations", std::to_string(options.generations) + " is negative");
  if (options.tournament < 1)
    throw InputError(source, "tournament", std::to_string(options.tournament) + " is below 1");
  if (!(options.mutationRate >= 0.0 && options.mutationRate <= 1.0)) {
    throw InputError(source, "mutationRate",
                     std::to_string(options.mutationRate) + " is not in [0, 1]");
  }
}

struct Individual {
  std::vector<int> giant;
  detail::Routes routes;
  detail::Score score;
};

class Genetic {
 public:
  Genetic(const detail::WorkCosts& costs, const detail::RoutingProblem& problem,
          const GeneticOptions& options)
      : c_(costs), problem_(problem), options_(options), rng_(options.seed) {}

  // Returns the best individual; initialBest receives the initial population's best.
  Individual run(Individual& initialBest) {
    std::vector<Individual> population;
    if (options_.seedWithHeuristic) {
      population.push_back(improved(detail::insertionRoutes(c_, problem_)));
    }
    while (static_cast<int>(population.size()) < options_.population)
      population.push_back(decoded(randomGiant()));
    Individual best = population[bestIndex(population)];
    initialBest = best;
    const int k = static_cast<int>(problem_.visit.size());
    for (int generation = 0; generation < options_.generations && k >= 2; ++generation) {
      std::vector<Individual> next;
      next.push_back(population[bestIndex(population)]);  // elitism
      while (static_cast<int>(next.size()) < options_.population) {
        const Individual& first = population[tournament(population)];
        const Individual& second = population[tournament(population)];
        std::vector<int> child = orderCrossover(first.giant, second.giant);
        if (rng_.uniform() < options_.mutationRate) mutate(child);
        next.push_back(decoded(std::move(child)));
      }
      population = std::move(next);
      const Individual& champion = population[bestIndex(population)];
      if (better(champion, best)) best = champion;
    }
    return best;
  }

  int64_t evaluations() const { return evaluations_; }

 private:
  bool better(const Individual& a, const Individual& b) const {
    return detail::better(problem_.objective, a.score, b.score, c_.epsilon());
  }
  size_t bestIndex(const std::vector<Individual>& population) const {
    size_t best = 0;
    for (size_t i = 1; i < population.size(); ++i) {
      if (better(population[i], population[best])) best = i;
    }
    return best;
  }
  size_t tournament(const std::vector<Individual>& population) {
    size_t winner = rng_.below(population.size());
    for (int draw = 1; draw < options_.tournament; ++draw) {
      const size_t challenger = rng_.below(population.size());
      if (better(population[challenger], population[winner])) winner = challenger;
    }
    return winner;
  }

  std::vector<int> randomGiant() {
    std::vector<int> giant = problem_.visit;
    for (size_t i = giant.size(); i > 1; --i)
      std::swap(giant[i - 1], giant[rng_.below(i)]);
    return giant;
  }

  Individual decoded(std::vector<int> giant) {
    return improved(detail::splitGiantTour(c_, problem_, giant));
  }
  // The memetic step (when enabled) and the encoding back to a giant tour (Lamarckian).
  Individual improved(detail::Routes routes) {
    if (options_.memetic) {
      detail::Budget budget{options_.search.maxEvaluations, 0};
      detail::iteratedRoutesSearch(c_, problem_, options_.search, budget, routes);
      evaluations_ += budget.used;
    }
    Individual individual;
    individual.giant = detail::giantTour(problem_, routes);
    individual.score = detail::scoreRoutes(c_, routes);
    individual.routes = std::move(routes);
    return individual;
  }

  // OX: a random stretch of the first parent in place, the rest in the second parent's order.
  std::vector<int> orderCrossover(const std::vector<int>& first, const std::vector<int>& second) {
    const size_t k = first.size();
    size_t from = rng_.below(k), to = rng_.below(k);
    if (from > to) std::swap(from, to);
    std::vector<int> child(k, -1);
    std::vector<char> taken(c_.size(), 0);
    for (size_t i = from; i <= to; ++i) {
      child[i] = first[i];
      taken[first[i]] = 1;
    }
    size_t place = (to + 1) % k;
    for (size_t t = 0; t < k; ++t) {
      const int node = second[(to + 1 + t) % k];
      if (taken[node]) continue;
      child[place] = node;
      place = (place + 1) % k;
    }
    return child;
  }

  // Swap two nodes, or reverse a stretch.
  void mutate(std::vector<int>& giant) {
    const size_t k = giant.size();
    size_t a = rng_.below(k), b = rng_.below(k);
    if (rng_.below(2) == 0) {
      std::swap(giant[a], giant[b]);
      return;
    }
    if (a > b) std::swap(a, b);
    std::reverse(giant.begin() + a, giant.begin() + b + 1);
  }

  const detail::WorkCosts& c_;
  const detail::RoutingProblem& problem_;
  const GeneticOptions& options_;
  Rng rng_;
  int64_t evaluations_ = 0;
};

}  // namespace

GeneticResult geneticMtsp(const CostMatrix& costs, const MtspProblem& problem,
                          const GeneticOptions& options) {
  validateOptions(options);
  const detail::RoutingProblem routing = detail::toRoutingProblem(costs, problem);
  const detail::WorkCosts work(costs);
  Genetic genetic(work, routing, options);
  Individual initialBest;
  Individual best = genetic.run(initialBest);
  GeneticResult result;
  result.best = detail::toSolution(costs, std::move(best.routes));
  result.initialBest = detail::toSolution(costs, std::move(initialBest.routes));
  result.evaluations = genetic.evaluations();
  return result;
}

Tour geneticTsp(const CostMatrix& costs, const TourProblem& problem, const GeneticOptions& options,
                double* initialCost) {
  validateOptions(options);
  const detail::RoutingProblem routing = detail::toRoutingProblem(costs, problem);
  const detail::WorkCosts work(costs);
  Genetic genetic(work, routing, options);
  Individual initialBest;
  Individual best = genetic.run(initialBest);
  if (initialCost) *initialCost = detail::toTour(costs, problem, initialBest.routes[0]).cost;
  return detail::toTour(costs, problem, std::move(best.routes[0]));
}

}  // namespace coinspect::planning
