#include "coinspect/world/oriented_box.h"

#include <cmath>
#include <sstream>

#include "coinspect/core/error.h"

namespace coinspect::world {

bool OrientedBox::contains(const Vec3& p, double margin) const {
  const Vec3 local = toBox(p);
  const Vec3 half = 0.5 * size + Vec3::Constant(margin);
  return (local.array().abs() <= half.array()).all();
}

std::array<Vec3, 8> OrientedBox::vertices() const {
  // Signs of the half sizes in the reference's order: the bottom face (z-) counter-clockwise
  // seen from above, then the top face in the same order.
  static constexpr double kSigns[8][3] = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1},
                                          {-1, -1, 1},  {1, -1, 1},  {1, 1, 1},  {-1, 1, 1}};
  std::array<Vec3, 8> corners;
  const Vec3 half = 0.5 * size;
  for (size_t i = 0; i < corners.size(); ++i) {
    const Vec3 local(kSigns[i][0] * half.x(), kSigns[i][1] * half.y(), kSigns[i][2] * half.z());
    corners[i] = center + rotation * local;
  }
  return corners;
}

void validateBox(const OrientedBox& box, const std::string& source) {
  const std::string where = "box '" + box.name + "'";
  if (!box.center.allFinite()) throw InputError(source, where, "center is not finite");
  if (!box.size.allFinite()) throw InputError(source, where, "size is not finite");
  if ((box.size.array() <= 0.0).any()) {
    std::ostringstream text;
    text << "size must be positive along every axis, got (" << box.size.x() << ", " << box.size.y()
         << ", " << box.size.z() << ")";
    throw InputError(source, where, text.str());
  }
  if (!box.rotation.allFinite()) throw InputError(source, where, "rotation is not finite");
  const double orthoError =
      (box.rotation.transpose() * box.rotation - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff();
  if (orthoError > 1e-6)
    throw InputError(source, where,
                     "rotation is not orthonormal (R^T R deviates from I by " +
                         std::to_string(orthoError) + ")");
  // A reflection would swap the box's handedness, and with it the reference's vertex order.
  if (std::abs(box.rotation.determinant() - 1.0) > 1e-6)
    throw InputError(source, where, "rotation has determinant -1 (a reflection)");
}

}  // namespace coinspect::world
