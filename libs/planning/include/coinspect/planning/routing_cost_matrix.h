// The input of every routing algorithm: a dense n x n matrix of travel costs between nodes.
//
// Costs may be asymmetric (cost(a, b) != cost(b, a), e.g. flight time with wind or climbing) and
// +infinity marks a forbidden edge. The diagonal is ignored. Costs are non-negative: they are
// distances or times, and the solvers rely on it to rank forbidden edges below every feasible tour.
#pragma once

#include <Eigen/Core>
#include <limits>
#include <vector>

namespace coinspect::planning {

inline constexpr double kForbidden = std::numeric_limits<double>::infinity();

class CostMatrix {
 public:
  CostMatrix() = default;
  // n nodes, every off-diagonal cost equal to `fill`.
  explicit CostMatrix(int n, double fill = 0.0);
  // n nodes from a row-major array of n * n costs (row = from, column = to). Throws InputError
  // for a wrong size, a NaN or a negative cost (the diagonal is not checked).
  CostMatrix(int n, std::vector<double> rowMajor);

  int size() const { return n_; }
  double operator()(int from, int to) const { return costs_[static_cast<size_t>(from) * n_ + to]; }
  // Throws InputError for a NaN or negative cost, or a node outside [0, n).
  void set(int from, int to, double cost);
  void forbid(int from, int to) { set(from, to, kForbidden); }

  bool isSymmetric() const;
  const std::vector<double>& rowMajor() const { return costs_; }

 private:
  int n_ = 0;
  std::vector<double> costs_;
};

// Straight-line distances between points (symmetric).
CostMatrix euclideanCostMatrix(const std::vector<Eigen::Vector3d>& points);

}  // namespace coinspect::planning
