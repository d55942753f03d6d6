#include "coinspect/world/mesh.h"

#include <cmath>

#include "coinspect/core/error.h"

namespace coinspect::world {

Eigen::Matrix3d MeshTransform::rotation() const {
  return (Eigen::AngleAxisd(yaw, Vec3::UnitZ()) * Eigen::AngleAxisd(pitch, Vec3::UnitY()) *
          Eigen::AngleAxisd(roll, Vec3::UnitX()))
      .toRotationMatrix();
}

bool MeshTransform::isIdentity() const {
  return scale == 1.0 && translation.isZero(0.0) && yaw == 0.0 && pitch == 0.0 && roll == 0.0;
}

Vec3 TriangleMesh::facetNormal(size_t triangle) const {
  const auto& t = triangles[triangle];
  const Vec3 n = (vertex(t[1]) - vertex(t[0])).cross(vertex(t[2]) - vertex(t[0]));
  const double length = n.norm();
  return length > 0.0 ? Vec3(n / length) : Vec3::Zero();
}

double TriangleMesh::facetArea(size_t triangle) const {
  const auto& t = triangles[triangle];
  return 0.5 * (vertex(t[1]) - vertex(t[0])).cross(vertex(t[2]) - vertex(t[0])).norm();
}

Aabb TriangleMesh::bounds() const {
  Aabb box;
  for (const auto& v : vertices) box.extend(v.cast<double>());
  return box;
}

void TriangleMesh::append(const TriangleMesh& other) {
  const auto offset = static_cast<uint32_t>(vertices.size());
  vertices.insert(vertices.end(), other.vertices.begin(), other.vertices.end());
  triangles.reserve(triangles.size() + other.triangles.size());
  for (const auto& t : other.triangles) triangles.push_back({t[0] + offset, t[1] + offset, t[2] + offset});
}

void TriangleMesh::transform(const MeshTransform& transform) {
  if (transform.isIdentity()) return;
  const Eigen::Matrix3d rotation = transform.rotation();
  for (auto& v : vertices)
    v = (transform.translation + rotation * (transform.scale * v.cast<double>())).cast<float>();
  // A mirroring (negative) scale flips facet orientation: keep normals outward.
  if (transform.scale < 0.0)
    for (auto& t : triangles) std::swap(t[1], t[2]);
}

void validateMesh(const TriangleMesh& mesh, const std::string& source) {
  if (mesh.triangles.empty() || mesh.vertices.empty())
    throw InputError(source, "", "mesh has no triangles");
  for (size_t i = 0; i < mesh.vertices.size(); ++i)
    if (!mesh.vertices[i].allFinite())
      throw InputError(source, "vertex " + std::to_string(i), "coordinate is not finite");
  size_t degenerate = 0;
  for (size_t i = 0; i < mesh.triangles.size(); ++i) {
    for (const uint32_t index : mesh.triangles[i])
      if (index >= mesh.vertices.size())
        throw InputError(source, "triangle " + std::to_string(i),
                         "vertex index " + std::to_string(index) + " out of range (" +
                             std::to_string(mesh.vertices.size()) + " vertices)");
    if (mesh.facetArea(i) <= 0.0) ++degenerate;
  }
  if (degenerate == mesh.triangles.size())
    throw InputError(source, "", "every triangle is degenerate (zero area)");
}

}  // namespace coinspect::world
