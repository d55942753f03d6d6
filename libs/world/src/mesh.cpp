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
// open border by 1. Real meshes have some edges shared by more: the CARIC MBS mesh has 67 of
// 103,247 (0.065%); a generated hangar whose walls are closed boxes touching along their edges has
// 90 of 594 (15%). Such meshes are fine to ray-cast, so only a large proportion is rejected: a
// mesh stored twice or three times, or a triangle soup stacked on itself, puts most edges over 2.
// Edges are compared by vertex position, not index, so a mesh is judged the same whether its
// parts share vertex indices (generated) or not (an STL file, whatever welding its loader did).
// Degenerate facets are left out: they bound nothing.
constexpr double kMaxNonManifoldEdgeFraction = 0.25;
// Facets repeated with the same vertices in the same cyclic order (the same face twice; a
// two-sided sheet has opposite orders and is not counted) may not make up half of the mesh.
constexpr double kMaxDuplicateFacetFraction = 0.5;

namespace {
// Maps every vertex index to the smallest index holding the same position.
std::vector<uint32_t> canonicalVertexIds(const std::vector<Eigen::Vector3f>& vertices) {
  std::vector<uint32_t> order(vertices.size());
  for (uint32_t i = 0; i < order.size(); ++i)
    order[i] = i;
  const auto lessByPosition = [&](uint32_t a, uint32_t b) {
    const auto &p = vertices[a], &q = vertices[b];
    if (p.x() != q.x()) return p.x() < q.x();
    if (p.y() != q.y()) return p.y() < q.y();
    if (p.z() != q.z()) return p.z() < q.z();
    return a < b;
  };
  std::sort(order.begin(), order.end(), lessByPosition);
  std::vector<uint32_t> canonical(vertices.size());
  for (size_t i = 0; i < order.size(); ++i)
    canonical[order[i]] =
        i > 0 && vertices[order[i]] == vertices[order[i - 1]] ? canonical[order[i - 1]] : order[i];
  return canonical;
}
}  // namespace

void validateMesh(const TriangleMesh& mesh, const std::string& source) {
  if (mesh.triangles.empty() || mesh.vertices.empty())
    throw InputError(source, "", "mesh has no triangles");
  for (size_t i = 0; i < mesh.vertices.size(); ++i)
    if (!mesh.vertices[i].allFinite())
      throw InputError(source, "vertex " + std::to_string(i), "coordinate is not finite");
  size_t degenerate = 0;
  const std::vector<uint32_t> canonical = canonicalVertexIds(mesh.vertices);
  // Undirected edges as (low << 32 | high), and facets rotated to start at their lowest index,
  // both over canonical (position) ids.
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
    const std::array<uint32_t, 3> c = {canonical[t[0]], canonical[t[1]], canonical[t[2]]};
    for (int k = 0; k < 3; ++k) {
      const uint64_t a = c[k], b = c[(k + 1) % 3];
      edges.push_back(a < b ? (a << 32 | b) : (b << 32 | a));
    }
    const int first = c[0] <= c[1] && c[0] <= c[2] ? 0 : (c[1] <= c[2] ? 1 : 2);
    facets.push_back({c[first], c[(first + 1) % 3], c[(first + 2) % 3]});
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
