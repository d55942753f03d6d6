// Random routing instances for the routing tests, reproducible by seed.
#pragma once

#include <algorithm>
#include <string>
#include <vector>

#include "coinspect/core/random.h"
#include "coinspect/planning/routing_cost_matrix.h"
#include "coinspect/planning/tour.h"

namespace coinspect::planning::routing_test {

enum class Shape {
  Euclidean,  // points in a 100 m square: symmetric
  Climbing,   // points in a 100 m cube; climbing costs 3x more than descending: asymmetric
  Uniform,    // independent uniform costs in [1, 100): asymmetric, no geometry
};

inline std::string name(Shape shape) {
  return shape == Shape::Euclidean ? "euclidean"
                                   : (shape == Shape::Climbing ? "climbing" : "uniform");
}

inline std::vector<Eigen::Vector3d> randomPoints(int n, uint64_t seed, double height = 0.0) {
  Rng rng(seed);
  std::vector<Eigen::Vector3d> points;
  for (int i = 0; i < n; ++i) {
    const double x = rng.uniform(0, 100), y = rng.uniform(0, 100), z = rng.uniform(0, height);
    points.emplace_back(x, y, z);
  }
  return points;
}

inline CostMatrix randomInstance(Shape shape, int n, uint64_t seed) {
  if (shape == Shape::Euclidean) return euclideanCostMatrix(randomPoints(n, seed));
  std::vector<double> costs(static_cast<size_t>(n) * n, 0.0);
  if (shape == Shape::Uniform) {
    Rng rng(seed);
    for (double& cost : costs)
      cost = rng.uniform(1.0, 100.0);
  } else {
    const auto points = randomPoints(n, seed, 100.0);
    for (int a = 0; a < n; ++a) {
      for (int b = 0; b < n; ++b) {
        const double climb = std::max(0.0, points[b].z() - points[a].z());
        costs[static_cast<size_t>(a) * n + b] = (points[b] - points[a]).norm() + 2.0 * climb;
      }
    }
  }
  return CostMatrix(n, std::move(costs));
}

// Closed, open with a free end, open with a fixed end.
inline std::vector<TourProblem> tourProblems(int n) {
  return {{TourKind::Closed, 0, -1}, {TourKind::Open, 0, -1}, {TourKind::Open, 0, n - 1}};
}

inline std::string name(const TourProblem& problem) {
  if (problem.kind == TourKind::Closed) return "closed";
  return problem.end < 0 ? "open" : "open-to-end";
}

}  // namespace coinspect::planning::routing_test
