#include "coinspect/world/mesh.h"

#include <algorithm>
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
  for (const auto& v : vertices)
    box.extend(v.cast<double>());
  return box;
}

void TriangleMesh::append(const TriangleMesh& other) {
  const auto offset = static_cast<uint32_t>(vertices.size());
  vertices.insert(vertices.end(), other.vertices.begin(), other.vertices.end());
  triangles.reserve(triangles.size() + other.triangles.size());
  for (const auto& t : other.triangles)
    triangles.push_back({t[0] + offset, t[1] + offset, t[2] + offset});
}

void TriangleMesh::transform(const MeshTransform& transform) {
  if (transform.isIdentity()) return;
  const Eigen::Matrix3d rotation = transform.rotation();
  for (auto& v : vertices)
    v = (transform.translation + rotation * (transform.scale * v.cast<double>())).cast<float>();
  // A mirroring (negative) scale flips facet orientation: keep normals outward.
  if (transform.scale < 0.0)
    for (auto& t : triangles)
      std::swap(t[1], t[2]);
}

// Edge-manifold rule. An edge of a closed surface is shared by exactly 2 facets, an edge on an
// open border by 1. Real scans and CAD exports have a few edges shared by more (the CARIC MBS
// mesh: 67 of 103,247 edges, 0.065%, are shared by 4 facets), so a handful is tolerated; garbage
// is caught by the proportion: a mesh stored twice, a triangle soup stacked on itself, or fans
// of facets around one edge put most edges over 2. Edges are compared by vertex index, so the
// rule needs shared vertices (loadMesh welds them by position); a mesh whose facets share no
// vertex has only border edges and passes. Degenerate facets are left out: they bound nothing.
constexpr double kMaxNonManifoldEdgeFraction = 0.1;
// Facets repeated with the same vertices in the same cyclic order (the same face twice; a
// two-sided sheet has opposite orders and is not counted) may not make up half of the mesh.
constexpr double kMaxDuplicateFacetFraction = 0.5;

void validateMesh(const TriangleMesh& mesh, const std::string& source) {
  if (mesh.triangles.empty() || mesh.vertices.empty())
    throw InputError(source, "", "mesh has no triangles");
  for (size_t i = 0; i < mesh.vertices.size(); ++i)
    if (!mesh.vertices[i].allFinite())
      throw InputError(source, "vertex " + std::to_string(i), "coordinate is not finite");
  size_t degenerate = 0;
  // Undirected edges as (low << 32 | high), and facets rotated to start at their lowest index.
  std::vector<uint64_t> edges;
  std::vector<std::array<uint32_t, 3>> facets;
  edges.reserve(3 * mesh.triangles.size());
  facets.reserve(mesh.triangles.size());
  for (size_t i = 0; i < mesh.triangles.size(); ++i) {
    const auto& t = mesh.triangles[i];
    for (const uint32_t index : t)
      if (index >= mesh.vertices.size())
        throw InputError(source, "triangle " + std::to_string(i),
                         "vertex index " + std::to_string(index) + " out of range (" +
                             std::to_string(mesh.vertices.size()) + " vertices)");
    if (mesh.facetArea(i) <= 0.0) {
      ++degenerate;
      continue;
    }
    for (int k = 0; k < 3; ++k) {
      const uint64_t a = t[k], b = t[(k + 1) % 3];
      edges.push_back(a < b ? (a << 32 | b) : (b << 32 | a));
    }
    const int first = t[0] <= t[1] && t[0] <= t[2] ? 0 : (t[1] <= t[2] ? 1 : 2);
    facets.push_back({t[first], t[(first + 1) % 3], t[(first + 2) % 3]});
  }
  if (degenerate == mesh.triangles.size())
    throw InputError(source, "", "every triangle is degenerate (zero area)");

  std::sort(facets.begin(), facets.end());
  const size_t distinctFacets =
      static_cast<size_t>(std::unique(facets.begin(), facets.end()) - facets.begin());
  const size_t duplicates = facets.size() - distinctFacets;
  if (static_cast<double>(duplicates) >= kMaxDuplicateFacetFraction * facets.size())
    throw InputError(source, "",
                     std::to_string(duplicates) + " of " + std::to_string(facets.size()) +
                         " non-degenerate triangles repeat another one");

  std::sort(edges.begin(), edges.end());
  size_t distinctEdges = 0, overShared = 0;
  for (size_t i = 0; i < edges.size();) {
    size_t j = i;
    while (j < edges.size() && edges[j] == edges[i])
      ++j;
    ++distinctEdges;
    if (j - i > 2) ++overShared;
    i = j;
  }
  if (static_cast<double>(overShared) > kMaxNonManifoldEdgeFraction * distinctEdges)
    throw InputError(source, "",
                     "non-manifold mesh: " + std::to_string(overShared) + " of " +
                         std::to_string(distinctEdges) +
                         " edges are shared by more than 2 triangles");
}

}  // namespace coinspect::world
