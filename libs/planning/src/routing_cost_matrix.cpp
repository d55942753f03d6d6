#include "coinspect/planning/routing_cost_matrix.h"

#include <cmath>
#include <string>

#include "coinspect/core/error.h"

namespace coinspect::planning {

namespace {

const char* const kSource = "cost matrix";

std::string cell(int from, int to) {
  return "row " + std::to_string(from) + ", column " + std::to_string(to);
}

void checkCost(int from, int to, double cost) {
  if (std::isnan(cost)) throw InputError(kSource, cell(from, to), "cost is NaN");
  if (cost < 0.0) {
    throw InputError(kSource, cell(from, to),
                     "cost " + std::to_string(cost) + " is negative (use +infinity to forbid)");
  }
}

}  // namespace

CostMatrix::CostMatrix(int n, double fill) {
  if (n < 0) throw InputError(kSource, "size", "negative node count " + std::to_string(n));
  checkCost(0, 1, fill);
  n_ = n;
  costs_.assign(static_cast<size_t>(n) * n, fill);
  for (int i = 0; i < n; ++i)
    costs_[static_cast<size_t>(i) * n + i] = 0.0;
}

CostMatrix::CostMatrix(int n, std::vector<double> rowMajor) {
  if (n < 0) throw InputError(kSource, "size", "negative node count " + std::to_string(n));
  if (rowMajor.size() != static_cast<size_t>(n) * n) {
    throw InputError(kSource, "size",
                     std::to_string(rowMajor.size()) + " costs given for " + std::to_string(n) +
                         " nodes (need " + std::to_string(static_cast<size_t>(n) * n) + ")");
  }
  for (int from = 0; from < n; ++from) {
    for (int to = 0; to < n; ++to) {
      if (from != to) checkCost(from, to, rowMajor[static_cast<size_t>(from) * n + to]);
    }
  }
  n_ = n;
  costs_ = std::move(rowMajor);
}

void CostMatrix::set(int from, int to, double cost) {
  if (from < 0 || from >= n_ || to < 0 || to >= n_) {
    throw InputError(kSource, cell(from, to),
                     "outside the matrix of " + std::to_string(n_) + " nodes");
  }
  checkCost(from, to, cost);
  costs_[static_cast<size_t>(from) * n_ + to] = cost;
}

bool CostMatrix::isSymmetric() const {
  for (int a = 0; a < n_; ++a) {
    for (int b = a + 1; b < n_; ++b) {
      if ((*this)(a, b) != (*this)(b, a)) return false;
    }
  }
  return true;
}

CostMatrix euclideanCostMatrix(const std::vector<Eigen::Vector3d>& points) {
  const int n = static_cast<int>(points.size());
  std::vector<double> costs(static_cast<size_t>(n) * n, 0.0);
  for (int a = 0; a < n; ++a) {
    for (int b = 0; b < n; ++b)
      costs[static_cast<size_t>(a) * n + b] = (points[a] - points[b]).norm();
  }
  return CostMatrix(n, std::move(costs));
}

}  // namespace coinspect::planning
