// Interest points: the surface samples a mission must photograph, with a radius search.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "coinspect/world/mesh.h"

namespace coinspect::world {

struct InterestPoint {
  Vec3 position = Vec3::Zero();
  Vec3 normal = Vec3::UnitZ();  // unit outward facet normal
  uint32_t index = 0;           // position in the scenario's list (the score.csv idx)
};

// Immutable set with a k-d tree over the positions.
class InterestPointSet {
 public:
  InterestPointSet();
  // Re-indexes the points 0..n-1 in the given order and builds the tree.
  explicit InterestPointSet(std::vector<InterestPoint> points);
  ~InterestPointSet();
  InterestPointSet(InterestPointSet&&) noexcept;
  InterestPointSet& operator=(InterestPointSet&&) noexcept;
  InterestPointSet(const InterestPointSet& other);
  InterestPointSet& operator=(const InterestPointSet& other);

  const std::vector<InterestPoint>& points() const { return points_; }
  size_t size() const { return points_.size(); }
  bool empty() const { return points_.empty(); }
  const InterestPoint& operator[](size_t i) const { return points_[i]; }

  // Indices of the points with |p - center| <= radius, ascending.
  void withinRadius(const Vec3& center, double radius, std::vector<uint32_t>& indices) const;
  std::vector<uint32_t> withinRadius(const Vec3& center, double radius) const;
  // Distance from point i to its nearest other point (spacing statistics); inf for one point.
  double nearestNeighbourDistance(size_t i) const;

 private:
  struct Tree;
  std::vector<InterestPoint> points_;
  std::unique_ptr<Tree> tree_;
};

// Throws InputError naming `source` and the point index for a non-finite position or a normal
// whose length is not 1 within 1e-3.
void validateInterestPoints(const std::vector<InterestPoint>& points, const std::string& source);

}  // namespace coinspect::world
