// Indexed triangle meshes: the solid geometry of a scenario.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <array>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

namespace coinspect::world {

using Vec3 = Eigen::Vector3d;

struct Aabb {
  Vec3 min = Vec3::Constant(std::numeric_limits<double>::infinity());
  Vec3 max = Vec3::Constant(-std::numeric_limits<double>::infinity());
  bool empty() const { return (min.array() > max.array()).any(); }
  void extend(const Vec3& p) {
    min = min.cwiseMin(p);
    max = max.cwiseMax(p);
  }
  Vec3 size() const { return max - min; }
};

// Placement of a loaded mesh: x_world = translation + rotation * (scale * x_file).
struct MeshTransform {
  double scale = 1.0;
  Vec3 translation = Vec3::Zero();
  // Z-Y-X Euler angles in radians (yaw about z first, as MRPT's CPose3D).
  double yaw = 0.0, pitch = 0.0, roll = 0.0;

  Eigen::Matrix3d rotation() const;
  Vec3 apply(const Vec3& p) const { return translation + rotation() * (scale * p); }
  bool isIdentity() const;
};

struct TriangleMesh {
  std::string name;
  // Single precision: what Embree consumes, and enough for millimetre detail over kilometres.
  std::vector<Eigen::Vector3f> vertices;
  std::vector<std::array<uint32_t, 3>> triangles;

  size_t triangleCount() const { return triangles.size(); }
  Vec3 vertex(uint32_t i) const { return vertices[i].cast<double>(); }
  // Unit normal by the right-hand rule over the vertex order (zero for a degenerate facet).
  Vec3 facetNormal(size_t triangle) const;
  double facetArea(size_t triangle) const;
  Aabb bounds() const;

  void append(const TriangleMesh& other);
  void transform(const MeshTransform& transform);
};

// Rejects what would break ray casting or scoring: no triangles, non-finite vertices, indices
// out of range, only degenerate (zero-area) facets, at least half of the facets repeating another
// one, or a non-manifold mesh (more than 10% of the edges shared by more than 2 facets; real
// meshes have a few such edges). Throws InputError naming `source` and the first offending
// triangle or vertex, or the counts.
void validateMesh(const TriangleMesh& mesh, const std::string& source);

}  // namespace coinspect::world
