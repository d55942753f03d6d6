// Small meshes built by hand for the world tests.
#pragma once

#include "coinspect/world/mesh.h"

namespace coinspect::world::test {

// Axis-aligned box [lo, hi] as 8 shared vertices and 12 triangles, counter-clockwise seen from
// outside (outward right-hand normals). Vertex i has x = hi.x when bit 0 of i is set, y when
// bit 1 is set, z when bit 2 is set.
inline TriangleMesh boxMesh(const Vec3& lo, const Vec3& hi, const std::string& name = "box") {
  TriangleMesh mesh;
  mesh.name = name;
  for (int i = 0; i < 8; ++i)
    mesh.vertices.emplace_back(static_cast<float>(i & 1 ? hi.x() : lo.x()),
                               static_cast<float>(i & 2 ? hi.y() : lo.y()),
                               static_cast<float>(i & 4 ? hi.z() : lo.z()));
  mesh.triangles = {{0, 2, 3}, {0, 3, 1},   // -z
                    {4, 5, 7}, {4, 7, 6},   // +z
                    {0, 1, 5}, {0, 5, 4},   // -y
                    {2, 6, 7}, {2, 7, 3},   // +y
                    {0, 4, 6}, {0, 6, 2},   // -x
                    {1, 3, 7}, {1, 7, 5}};  // +x
  return mesh;
}

// Square wall in the plane x = x0, |y| <= half, |z| <= half, facing -x.
inline TriangleMesh wallMesh(double x0, double half) {
  TriangleMesh mesh;
  mesh.name = "wall";
  const auto f = [](double v) { return static_cast<float>(v); };
  mesh.vertices = {{f(x0), f(-half), f(-half)},
                   {f(x0), f(half), f(-half)},
                   {f(x0), f(half), f(half)},
                   {f(x0), f(-half), f(half)}};
  // (v1 - v0) x (v2 - v0) = (0, 2h, 0) x (0, 2h, 2h) = (4h^2, 0, 0): that faces +x, so reverse.
  mesh.triangles = {{0, 2, 1}, {0, 3, 2}};
  return mesh;
}

}  // namespace coinspect::world::test
