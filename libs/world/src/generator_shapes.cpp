// Closed mesh primitives for the scenario generators.
#include <cmath>

#include "coinspect/core/error.h"
#include "generator_detail.h"

namespace coinspect::world::detail {

namespace {

uint32_t addVertex(TriangleMesh& mesh, const Vec3& p) {
  mesh.vertices.push_back(p.cast<float>());
  return static_cast<uint32_t>(mesh.vertices.size() - 1);
}

Vec3 centroid(const std::vector<Vec3>& ring) {
  Vec3 sum = Vec3::Zero();
  for (const Vec3& p : ring)
    sum += p;
  return sum / static_cast<double>(ring.size());
}

double cross2(const Vec2& a, const Vec2& b) {
  return a.x() * b.y() - a.y() * b.x();
}

double polygonArea(const std::vector<Vec2>& polygon) {
  double area = 0.0;
  for (size_t i = 0; i < polygon.size(); ++i)
    area += cross2(polygon[i], polygon[(i + 1) % polygon.size()]);
  return 0.5 * area;
}

Vec2 areaCentroid(const std::vector<Vec2>& polygon) {
  Vec2 sum = Vec2::Zero();
  double area = 0.0;
  for (size_t i = 0; i < polygon.size(); ++i) {
    const Vec2& a = polygon[i];
    const Vec2& b = polygon[(i + 1) % polygon.size()];
    const double c = cross2(a, b);
    area += c;
    sum += (a + b) * c;
  }
  COINSPECT_ASSERT(std::abs(area) > 0.0);
  return sum / (3.0 * area);
}

}  // namespace

Eigen::Matrix3d yawRotation(double yaw) {
  return Eigen::AngleAxisd(yaw, Vec3::UnitZ()).toRotationMatrix();
}

Vec2 rotate2(const Vec2& p, double angle) {
  const double c = std::cos(angle), s = std::sin(angle);
  return {c * p.x() - s * p.y(), s * p.x() + c * p.y()};
}

double signedVolume(const TriangleMesh& mesh) {
  // Relative to a vertex of the mesh: keeps the float-sized terms small far from the origin.
  if (mesh.vertices.empty()) return 0.0;
  const Vec3 origin = mesh.vertex(0);
  double volume = 0.0;
  for (const auto& t : mesh.triangles) {
    const Vec3 a = mesh.vertex(t[0]) - origin;
    const Vec3 b = mesh.vertex(t[1]) - origin;
    const Vec3 c = mesh.vertex(t[2]) - origin;
    volume += a.dot(b.cross(c));
  }
  return volume / 6.0;
}

void orientOutward(TriangleMesh& mesh) {
  if (signedVolume(mesh) < 0.0)
    for (auto& t : mesh.triangles)
      std::swap(t[1], t[2]);
}

TriangleMesh makeLoft(const std::vector<std::vector<Vec3>>& rings,
                      const std::optional<Vec3>& bottomApex, const std::optional<Vec3>& topApex) {
  COINSPECT_ASSERT(!rings.empty());
  const size_t n = rings.front().size();
  COINSPECT_ASSERT(n >= 3);
  TriangleMesh mesh;
  std::vector<std::vector<uint32_t>> ids;
  for (const auto& ring : rings) {
    COINSPECT_ASSERT(ring.size() == n);
    std::vector<uint32_t> row;
    for (const Vec3& p : ring)
      row.push_back(addVertex(mesh, p));
    ids.push_back(std::move(row));
  }
  // One consistent winding everywhere; orientOutward flips the whole mesh if it is inward.
  for (size_t r = 0; r + 1 < ids.size(); ++r)
    for (size_t j = 0; j < n; ++j) {
      const size_t k = (j + 1) % n;
      mesh.triangles.push_back({ids[r][j], ids[r][k], ids[r + 1][k]});
      mesh.triangles.push_back({ids[r][j], ids[r + 1][k], ids[r + 1][j]});
    }
  const uint32_t bottom = addVertex(mesh, bottomApex ? *bottomApex : centroid(rings.front()));
  const uint32_t top = addVertex(mesh, topApex ? *topApex : centroid(rings.back()));
  for (size_t j = 0; j < n; ++j) {
    const size_t k = (j + 1) % n;
    mesh.triangles.push_back({bottom, ids.front()[k], ids.front()[j]});
    mesh.triangles.push_back({top, ids.back()[j], ids.back()[k]});
  }
  orientOutward(mesh);
  return mesh;
}

TriangleMesh makeExtrusion(const std::vector<Vec2>& polygon, const Vec3& origin, const Vec3& u,
                           const Vec3& v, const Vec3& along, const std::optional<Vec2>& fanCenter) {
  COINSPECT_ASSERT(polygon.size() >= 3);
  const Vec2 center = fanCenter ? *fanCenter : areaCentroid(polygon);
  // Caps are fans from `center`: every fan triangle must turn the same way as the polygon.
  const double sign = polygonArea(polygon) > 0.0 ? 1.0 : -1.0;
  for (size_t i = 0; i < polygon.size(); ++i)
    COINSPECT_ASSERT(
        sign * cross2(polygon[i] - center, polygon[(i + 1) % polygon.size()] - center) > 0.0);
  std::vector<Vec3> bottom, top;
  for (const Vec2& p : polygon) {
    bottom.push_back(origin + p.x() * u + p.y() * v);
    top.push_back(bottom.back() + along);
  }
  const Vec3 c = origin + center.x() * u + center.y() * v;
  return makeLoft({bottom, top}, c, Vec3(c + along));
}

TriangleMesh makePrism(const std::vector<Vec2>& polygon, double z0, double z1,
                       const std::optional<Vec2>& fanCenter) {
  return makeExtrusion(polygon, Vec3(0, 0, z0), Vec3::UnitX(), Vec3::UnitY(), Vec3(0, 0, z1 - z0),
                       fanCenter);
}

TriangleMesh makeBox(const Vec3& center, const Vec3& size, const Eigen::Matrix3d& rotation) {
  const Vec3 u = rotation.col(0), v = rotation.col(1), w = rotation.col(2);
  return makeExtrusion(rectangle(Vec2::Zero(), size.x(), size.y()), center - 0.5 * size.z() * w, u,
                       v, size.z() * w);
}

TriangleMesh makeBox(const Vec3& center, const Vec3& size, double yaw) {
  return makeBox(center, size, yawRotation(yaw));
}

TriangleMesh makeBeam(const Vec3& a, const Vec3& b, double width) {
  const Vec3 axis = b - a;
  COINSPECT_ASSERT(axis.norm() > 0.0);
  const Vec3 d = axis.normalized();
  const Vec3 reference = std::abs(d.z()) < 0.9 ? Vec3::UnitZ() : Vec3::UnitX();
  const Vec3 u = d.cross(reference).normalized();
  const Vec3 v = d.cross(u);
  return makeExtrusion(rectangle(Vec2::Zero(), width, width), a, u, v, axis);
}

TriangleMesh makeFrustum(const Vec3& baseCenter, double r0, double r1, double height,
                         int segments) {
  COINSPECT_ASSERT(segments >= 3 && r0 > 0.0 && height > 0.0);
  std::vector<std::vector<Vec3>> rings(r1 > 0.0 ? 2 : 1);
  for (int i = 0; i < segments; ++i) {
    const double a = 2.0 * M_PI * i / segments;
    const Vec3 dir(std::cos(a), std::sin(a), 0.0);
    rings[0].push_back(baseCenter + r0 * dir);
    if (r1 > 0.0) rings[1].push_back(baseCenter + r1 * dir + Vec3(0, 0, height));
  }
  // With r1 = 0 the single ring's top fan is the cone; otherwise it is the flat top cap.
  return makeLoft(rings, baseCenter, Vec3(baseCenter + Vec3(0, 0, height)));
}

TriangleMesh makeEllipsoid(const Vec3& center, const Vec3& radii, const Eigen::Matrix3d& rotation,
                           int slices, int stacks) {
  COINSPECT_ASSERT(slices >= 3 && stacks >= 2);
  std::vector<std::vector<Vec3>> rings;
  // From the south pole upwards, so that the apexes below close the two ends.
  for (int k = stacks - 1; k >= 1; --k) {
    const double phi = M_PI * k / stacks;
    std::vector<Vec3> ring;
    for (int i = 0; i < slices; ++i) {
      const double theta = 2.0 * M_PI * i / slices;
      const Vec3 local(radii.x() * std::sin(phi) * std::cos(theta),
                       radii.y() * std::sin(phi) * std::sin(theta), radii.z() * std::cos(phi));
      ring.push_back(center + rotation * local);
    }
    rings.push_back(std::move(ring));
  }
  const Vec3 south = center - rotation.col(2) * radii.z();
  const Vec3 north = center + rotation.col(2) * radii.z();
  return makeLoft(rings, south, north);
}

std::vector<Vec2> regularPolygon(const Vec2& center, double radius, int sides, double phase) {
  std::vector<Vec2> polygon;
  for (int i = 0; i < sides; ++i) {
    const double a = phase + 2.0 * M_PI * i / sides;
    polygon.emplace_back(center + radius * Vec2(std::cos(a), std::sin(a)));
  }
  return polygon;
}

std::vector<Vec2> rectangle(const Vec2& center, double sizeX, double sizeY, double yaw) {
  const double hx = 0.5 * sizeX, hy = 0.5 * sizeY;
  return {center + rotate2({-hx, -hy}, yaw), center + rotate2({hx, -hy}, yaw),
          center + rotate2({hx, hy}, yaw), center + rotate2({-hx, hy}, yaw)};
}

std::vector<Vec2> yPlan(const std::vector<double>& lengths, double halfWidth, double phase,
                        int tipSegments) {
  COINSPECT_ASSERT(lengths.size() == 3 && tipSegments >= 1);
  std::vector<Vec2> polygon;
  for (int i = 0; i < 3; ++i) {
    const double theta = phase + M_PI / 2 + 2.0 * M_PI * i / 3.0;
    const Vec2 d(std::cos(theta), std::sin(theta));
    const Vec2 p(-d.y(), d.x());
    // The re-entrant corner between the previous wing and this one lies on their bisector, at
    // the distance where both wing edges (offset halfWidth from the axes) meet.
    const double bisector = theta - M_PI / 3.0;
    polygon.emplace_back(halfWidth / std::sin(M_PI / 3.0) *
                         Vec2(std::cos(bisector), std::sin(bisector)));
    const double straight = lengths[static_cast<size_t>(i)] - halfWidth;
    COINSPECT_ASSERT(straight > halfWidth);
    for (int s = 0; s <= tipSegments; ++s) {
      const double a = -M_PI / 2 + M_PI * s / tipSegments;
      polygon.emplace_back(straight * d + halfWidth * (std::cos(a) * d + std::sin(a) * p));
    }
  }
  return polygon;
}

}  // namespace coinspect::world::detail
