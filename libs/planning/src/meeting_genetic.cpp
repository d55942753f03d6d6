// OptMeet's genetic algorithm and its polish (declared in meeting_route.h).
#include "coinspect/planning/meeting_route.h"

#include <algorithm>
#include <limits>
#include <numeric>

#include "coinspect/core/random.h"
#include "meeting_internal.h"

namespace coinspect::planning {

namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

// The GA of meeting_route.h, then the polish. Chromosomes live in one flat array (row i is
// individual i), so a generation allocates nothing.
class MeetingGenetic {
 public:
  MeetingGenetic(const ExplorerState& explorer,
                 const std::vector<const detail::MeetingGenePool*>& pools,
                 const MeetingRouteOptions& options, uint64_t seed)
      : explorer_(explorer), pools_(pools), options_(options), genes_(pools.size()), rng_(seed) {}

  // The best chromosome seen over all generations, polished.
  std::vector<int> run() {
    size_t size = static_cast<size_t>(options_.ga.population);
    for (const detail::MeetingGenePool* pool : pools_)
      size = std::max(size, pool->poseCount());
    std::vector<int> population(size * genes_), next(size * genes_);
    std::vector<double> costs(size), nextCosts(size);
    for (size_t i = 0; i < size; ++i) {
      initial(i, &population[i * genes_]);
      costs[i] = cost(&population[i * genes_]);
    }
    size_t bestIndex = std::min_element(costs.begin(), costs.end()) - costs.begin();
    std::vector<int> best(population.begin() + bestIndex * genes_,
                          population.begin() + (bestIndex + 1) * genes_);
    double bestCost = costs[bestIndex];

    const size_t parents = std::max<size_t>(1, size / 2);
    const size_t elites = std::min(size, static_cast<size_t>(options_.ga.elites));
    std::vector<size_t> rank(size);
    for (int generation = 0; generation < options_.ga.generations; ++generation) {
      std::iota(rank.begin(), rank.end(), 0);
      std::stable_sort(rank.begin(), rank.end(),
                       [&costs](size_t a, size_t b) { return costs[a] < costs[b]; });
      for (size_t i = 0; i < size; ++i) {
        int* child = &next[i * genes_];
        if (i < elites) {
          std::copy_n(&population[rank[i] * genes_], genes_, child);
          nextCosts[i] = costs[rank[i]];
          continue;
        }
        const int* first = &population[rank[rng_.below(parents)] * genes_];
        const int* second = &population[rank[rng_.below(parents)] * genes_];
        crossover(first, second, child);
        mutate(child);
        nextCosts[i] = cost(child);
      }
      population.swap(next);
      costs.swap(nextCosts);
      for (size_t i = 0; i < size; ++i) {
        if (costs[i] < bestCost) {
          bestCost = costs[i];
          std::copy_n(&population[i * genes_], genes_, best.begin());
        }
      }
    }
    if (options_.ga.polishSweeps == 0) return best;  // the reference's GA
    // Coordinate descent from the GA's best and from the greedy route; the better one wins.
    polish(best, bestCost);
    std::vector<int> myopic = greedy();
    double myopicCost = cost(myopic.data());
    polish(myopic, myopicCost);
    return myopicCost < bestCost ? myopic : best;
  }

 private:
  void initial(size_t individual, int* genes) {
    for (size_t k = 0; k < genes_; ++k) {
      const detail::MeetingGenePool& pool = *pools_[k];
      const size_t pose = individual % pool.poseCount();
      const size_t begin = pool.poseBegin[pose], end = pool.poseBegin[pose + 1];
      genes[k] = static_cast<int>(end > begin ? begin + rng_.below(end - begin)
                                              : rng_.below(pool.candidates.size()));
    }
  }

  void crossover(const int* first, const int* second, int* child) {
    std::copy_n(first, genes_, child);
    if (genes_ < 2) return;
    const size_t cut = 1 + rng_.below(genes_ - 1);  // both parents give at least a gene
    std::copy(second + cut, second + genes_, child + cut);
  }

  void mutate(int* genes) {
    for (size_t k = 0; k < genes_; ++k) {
      if (rng_.uniform() < options_.ga.mutationRate)
        genes[k] = static_cast<int>(rng_.below(pools_[k]->candidates.size()));
    }
  }

  const detail::MeetingCandidate& candidate(size_t k, int gene) const {
    return pools_[k]->candidates[gene];
  }

  // The cost of legs k, k + 1, ... starting from `position` at `clock`; +infinity if infeasible.
  double suffixCost(const int* genes, size_t k, Vec3 position, double clock) const {
    double total = 0.0;
    for (; k < genes_; ++k) {
      const detail::MeetingCandidate& to = candidate(k, genes[k]);
      const detail::MeetingLeg leg = detail::meetingLeg(position, clock, to, options_.explorer);
      if (!leg.feasible) return kInfinity;
      total += leg.cost();
      position = to.point;
      clock = leg.meetingTime;
    }
    return total;
  }

  double cost(const int* genes) const {
    return suffixCost(genes, 0, explorer_.position, explorer_.now);
  }

  // Each inspector in turn at the candidate with the cheapest leg from where the explorer is
  // (the first candidate when none is feasible).
  std::vector<int> greedy() const {
    std::vector<int> genes(genes_, 0);
    Vec3 position = explorer_.position;
    double clock = explorer_.now;
    for (size_t k = 0; k < genes_; ++k) {
      const detail::MeetingGenePool& pool = *pools_[k];
      double bestLeg = kInfinity;
      for (size_t pose = 0; pose < pool.poseCount(); ++pose) {
        if (!(poseBound(pool.poses[pose], position, clock, nullptr) < bestLeg)) continue;
        for (size_t c = pool.poseBegin[pose]; c < pool.poseBegin[pose + 1]; ++c) {
          const detail::MeetingLeg leg =
              detail::meetingLeg(position, clock, pool.candidates[c], options_.explorer);
          if (leg.feasible && leg.cost() < bestLeg) {
            bestLeg = leg.cost();
            genes[k] = static_cast<int>(c);
          }
        }
      }
      const detail::MeetingLeg leg =
          detail::meetingLeg(position, clock, candidate(k, genes[k]), options_.explorer);
      position = candidate(k, genes[k]).point;
      clock = leg.meetingTime;
    }
    return genes;
  }

  // A lower bound on leg k's cost plus the travel of leg k + 1 for any candidate of a pose:
  // they all lie within `radius` of its centre. +infinity when none can make the window.
  double poseBound(const detail::MeetingPoseSummary& pose, const Vec3& position, double clock,
                   const Vec3* nextPoint) const {
    const TravelLimits& limits = options_.explorer;
    const double travel =
        travelTime(std::max(0.0, (pose.centre - position).norm() - pose.radius), limits);
    const double arrival = clock + travel;
    if (arrival > pose.window.end) return kInfinity;
    double bound = travel + std::max(0.0, pose.window.start - arrival) +
                   std::max(0.0, arrival - pose.window.idleSince);
    if (nextPoint)
      bound += travelTime(std::max(0.0, (*nextPoint - pose.centre).norm() - pose.radius), limits);
    return bound;
  }

  // Coordinate descent on the GA's answer: each gene in turn takes the candidate that makes the
  // whole route cheapest with the other genes fixed, until a sweep changes nothing. The GA alone
  // tries only a few dozen of an inspector's candidates (population 20, mutation 0.01).
  void polish(std::vector<int>& genes, double& bestCost) const {
    const TravelLimits& limits = options_.explorer;
    for (int sweep = 0; sweep < options_.ga.polishSweeps; ++sweep) {
      bool changed = false;
      Vec3 position = explorer_.position;
      double clock = explorer_.now, prefix = 0.0;
      for (size_t k = 0; k < genes_; ++k) {
        // Legs after k + 1 join fixed points: their travel is a constant part of every option.
        double laterTravel = 0.0;
        for (size_t j = k + 2; j < genes_; ++j) {
          laterTravel += travelTime(
              (candidate(j, genes[j]).point - candidate(j - 1, genes[j - 1]).point).norm(), limits);
        }
        const Vec3* nextPoint = k + 1 < genes_ ? &candidate(k + 1, genes[k + 1]).point : nullptr;
        const detail::MeetingGenePool& pool = *pools_[k];
        for (size_t pose = 0; pose < pool.poseCount(); ++pose) {
          if (!(poseBound(pool.poses[pose], position, clock, nextPoint) + prefix + laterTravel <
                bestCost)) {
            continue;  // no candidate of this pose can do better
          }
          for (size_t c = pool.poseBegin[pose]; c < pool.poseBegin[pose + 1]; ++c) {
            const detail::MeetingCandidate& option = pool.candidates[c];
            const detail::MeetingLeg first = detail::meetingLeg(position, clock, option, limits);
            double total = prefix + first.cost();
            if (!first.feasible || !(total < bestCost)) continue;
            // Waiting only adds to the travel still to come: a cheap bound before the full walk.
            if (nextPoint) {
              const double rest = travelTime((*nextPoint - option.point).norm(), limits);
              if (!(total + rest + laterTravel < bestCost)) continue;
            }
            Vec3 at = option.point;
            double time = first.meetingTime;
            for (size_t j = k + 1; j < genes_ && total < bestCost; ++j) {
              const detail::MeetingCandidate& to = candidate(j, genes[j]);
              const detail::MeetingLeg leg = detail::meetingLeg(at, time, to, limits);
              total = leg.feasible ? total + leg.cost() : kInfinity;
              at = to.point;
              time = leg.meetingTime;
            }
            if (total < bestCost) {
              bestCost = total;
              genes[k] = static_cast<int>(c);
              changed = true;
            }
          }
        }
        const detail::MeetingLeg leg =
            detail::meetingLeg(position, clock, candidate(k, genes[k]), limits);
        if (!leg.feasible) break;  // later genes cannot repair an earlier missed window
        prefix += leg.cost();
        position = candidate(k, genes[k]).point;
        clock = leg.meetingTime;
      }
      if (!changed) break;
    }
  }

  const ExplorerState& explorer_;
  const std::vector<const detail::MeetingGenePool*>& pools_;
  const MeetingRouteOptions& options_;
  const size_t genes_;
  Rng rng_;
};

}  // namespace

namespace detail {

MeetingRoute optimiseOnPools(const ExplorerState& explorer,
                             const std::vector<InspectorPlan>& inspectors,
                             const std::vector<InspectorMeetingPoints>& points,
                             const std::vector<int>& order,
                             const std::vector<const MeetingGenePool*>& pools,
                             const MeetingRouteOptions& options, uint64_t seed) {
  for (const MeetingGenePool* pool : pools) {
    if (pool->candidates.empty()) return MeetingRoute{};  // this inspector cannot be met
  }
  MeetingGenetic genetic(explorer, pools, options, seed);
  const std::vector<int> best = genetic.run();
  std::vector<MeetingPick> picks;
  for (size_t k = 0; k < best.size(); ++k)
    picks.push_back(pools[k]->candidates[best[k]].pick);
  return evaluateMeetingRoute(explorer, inspectors, points, order, picks, options);
}

}  // namespace detail

MeetingRoute optimiseMeetingRoute(const ExplorerState& explorer,
                                  const std::vector<InspectorPlan>& inspectors,
                                  const std::vector<InspectorMeetingPoints>& points,
                                  const std::vector<int>& order, const MeetingRouteOptions& options,
                                  uint64_t seed) {
  validateMeetingRoute(options);
  detail::validateMeetingInputs(inspectors, points, order);
  std::vector<detail::MeetingGenePool> pools;
  for (const int index : order) {
    pools.push_back(detail::meetingGenePool(inspectors[index], points[index], explorer.now,
                                            options.inspectionTime));
  }
  std::vector<const detail::MeetingGenePool*> pointers;
  for (const detail::MeetingGenePool& pool : pools)
    pointers.push_back(&pool);
  return detail::optimiseOnPools(explorer, inspectors, points, order, pointers, options, seed);
}

}  // namespace coinspect::planning
