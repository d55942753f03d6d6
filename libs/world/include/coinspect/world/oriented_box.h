// Oriented bounding boxes: the regions whose surfaces must be inspected.
#pragma once

#include <array>
#include <string>

#include "coinspect/world/mesh.h"

namespace coinspect::world {

struct OrientedBox {
  std::string name;
  Vec3 center = Vec3::Zero();
  Vec3 size = Vec3::Zero();  // full edge lengths along the box axes
  // Columns are the box axes in the world frame: x_world = center + rotation * x_box.
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();

  // Inclusive containment, with the box grown by `margin` on every side.
  bool contains(const Vec3& p, double margin = 0.0) const;
  // The reference's vertex order: (-,-,-),(+,-,-),(+,+,-),(-,+,-),(-,-,+),(+,-,+),(+,+,+),(-,+,+)
  // in box coordinates (signs of half sizes).
  std::array<Vec3, 8> vertices() const;
  double volume() const { return size.prod(); }
  Vec3 toBox(const Vec3& p) const { return rotation.transpose() * (p - center); }
};

// Throws InputError naming `source` and the box when a size is not positive, a value is not
// finite or the rotation is not orthonormal with determinant +1 (tolerance 1e-6).
void validateBox(const OrientedBox& box, const std::string& source);

}  // namespace coinspect::world
