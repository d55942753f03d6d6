#include "coinspect/world/interest_points.h"

#include <nanoflann.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

#include "coinspect/core/error.h"

namespace coinspect::world {

// The tree owns its own copy of the coordinates: nanoflann keeps a reference to the dataset, and
// a heap-allocated Tree keeps that reference valid when the set is moved.
struct InterestPointSet::Tree {
  struct Adaptor {
    const std::vector<Vec3>* positions;
    size_t kdtree_get_point_count() const { return positions->size(); }
    double kdtree_get_pt(size_t i, size_t dim) const { return (*positions)[i][dim]; }
    template <class Bbox>
    bool kdtree_get_bbox(Bbox& /*unused*/) const {
      return false;
    }
  };
  using Index = nanoflann::KDTreeSingleIndexAdaptor<nanoflann::L2_Simple_Adaptor<double, Adaptor>,
                                                    Adaptor, 3, uint32_t>;

  explicit Tree(const std::vector<InterestPoint>& points)
      : adaptor{&positions}, index(3, adaptor, nanoflann::KDTreeSingleIndexAdaptorParams(10)) {
    positions.reserve(points.size());
    for (const auto& p : points)
      positions.push_back(p.position);
    index.buildIndex();
  }

  std::vector<Vec3> positions;
  Adaptor adaptor;
  Index index;
};

InterestPointSet::InterestPointSet() = default;

InterestPointSet::InterestPointSet(std::vector<InterestPoint> points) : points_(std::move(points)) {
  for (size_t i = 0; i < points_.size(); ++i)
    points_[i].index = static_cast<uint32_t>(i);
  if (!points_.empty()) tree_ = std::make_unique<Tree>(points_);
}

InterestPointSet::~InterestPointSet() = default;
InterestPointSet::InterestPointSet(InterestPointSet&&) noexcept = default;
InterestPointSet& InterestPointSet::operator=(InterestPointSet&&) noexcept = default;

InterestPointSet::InterestPointSet(const InterestPointSet& other) : points_(other.points_) {
  if (!points_.empty()) tree_ = std::make_unique<Tree>(points_);
}

InterestPointSet& InterestPointSet::operator=(const InterestPointSet& other) {
  if (this != &other) *this = InterestPointSet(other);
  return *this;
}

void InterestPointSet::withinRadius(const Vec3& center, double radius,
                                    std::vector<uint32_t>& indices) const {
  indices.clear();
  if (!tree_ || !(radius >= 0.0)) return;
  const double radiusSq = radius * radius;
  // nanoflann keeps only d^2 < r^2 (strict); search a slightly larger ball and decide membership
  // here with the inclusive test, so points exactly on the sphere are found.
  const double searchSq = radiusSq * (1.0 + 1e-9) + 1e-12;
  std::vector<std::pair<uint32_t, double>> found;
  tree_->index.radiusSearch(center.data(), searchSq, found,
                            nanoflann::SearchParams(32, 0.f, false));
  indices.reserve(found.size());
  for (const auto& [index, ignored] : found)
    if ((points_[index].position - center).squaredNorm() <= radiusSq) indices.push_back(index);
  std::sort(indices.begin(), indices.end());
}

std::vector<uint32_t> InterestPointSet::withinRadius(const Vec3& center, double radius) const {
  std::vector<uint32_t> indices;
  withinRadius(center, radius, indices);
  return indices;
}

double InterestPointSet::nearestNeighbourDistance(size_t i) const {
  COINSPECT_ASSERT(i < points_.size());
  if (points_.size() < 2) return std::numeric_limits<double>::infinity();
  // The query point finds itself first (or a duplicate at distance 0, which is the answer).
  uint32_t indices[2];
  double distancesSq[2];
  const size_t n = tree_->index.knnSearch(points_[i].position.data(), 2, indices, distancesSq);
  COINSPECT_ASSERT(n == 2);
  const uint32_t other = indices[0] == i ? indices[1] : indices[0];
  return (points_[other].position - points_[i].position).norm();
}

void validateInterestPoints(const std::vector<InterestPoint>& points, const std::string& source) {
  for (size_t i = 0; i < points.size(); ++i) {
    const auto& p = points[i];
    const std::string where = "interest point " + std::to_string(i);
    if (!p.position.allFinite()) throw InputError(source, where, "position is not finite");
    if (!p.normal.allFinite()) throw InputError(source, where, "normal is not finite");
    const double length = p.normal.norm();
    if (std::abs(length - 1.0) > 1e-3)
      throw InputError(source, where,
                       "normal is not a unit vector (length " + std::to_string(length) + ")");
  }
}

}  // namespace coinspect::world
