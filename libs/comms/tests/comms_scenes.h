// Small hand-made scenes for the comms tests: walls and boxes on the ground plane z = 0.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "coinspect/comms/link_model.h"
#include "coinspect/world/mesh.h"

namespace coinspect::comms::test {

using world::Vec3;

// Axis-aligned box [lo, hi]: 8 vertices, 12 outward-facing triangles.
inline world::TriangleMesh boxMesh(const Vec3& lo, const Vec3& hi,
                                   const std::string& name = "box") {
  world::TriangleMesh mesh;
  mesh.name = name;
  for (int i = 0; i < 8; ++i)
    mesh.vertices.emplace_back(static_cast<float>(i & 1 ? hi.x() : lo.x()),
                               static_cast<float>(i & 2 ? hi.y() : lo.y()),
                               static_cast<float>(i & 4 ? hi.z() : lo.z()));
  mesh.triangles = {{0, 2, 3}, {0, 3, 1}, {4, 5, 7}, {4, 7, 6}, {0, 1, 5}, {0, 5, 4},
                    {2, 6, 7}, {2, 7, 3}, {0, 4, 6}, {0, 6, 2}, {1, 3, 7}, {1, 7, 5}};
  return mesh;
}

// A wall 0.2 m thick across the x axis: x in [-0.1, 0.1], |y| <= 5, z in [0, height].
inline world::TriangleMesh wallAcrossX(double height) {
  return boxMesh(Vec3(-0.1, -5.0, 0.0), Vec3(0.1, 5.0, height), "wall");
}

// A zero-thickness square in the plane x = 0, |y| <= 5, z in [0, 10].
inline world::TriangleMesh thinPanelAtXZero() {
  world::TriangleMesh mesh;
  mesh.name = "panel";
  mesh.vertices = {{0.f, -5.f, 0.f}, {0.f, 5.f, 0.f}, {0.f, 5.f, 10.f}, {0.f, -5.f, 10.f}};
  mesh.triangles = {{0, 2, 1}, {0, 3, 2}};
  return mesh;
}

inline LinkEndpoint endpoint(const Vec3& position, double antennaOffset = 0.2, bool alive = true) {
  LinkEndpoint e;
  e.position = position;
  e.antennaOffset = antennaOffset;
  e.alive = alive;
  return e;
}

// The reference's rule written as plainly as possible: one segmentClear per antenna pair.
inline LinkMatrix naiveCaricTopology(const world::RayCaster& caster,
                                     const std::vector<LinkEndpoint>& units) {
  LinkMatrix links(units.size());
  for (uint32_t i = 0; i < units.size(); ++i)
    for (uint32_t j = i + 1; j < units.size(); ++j) {
      if (!units[i].alive || !units[j].alive) continue;
      const auto a = antennaPositions(units[i], caster.hasGround(), caster.groundZ());
      const auto b = antennaPositions(units[j], caster.hasGround(), caster.groundZ());
      bool clear = false;
      for (const Vec3& pa : a)
        for (const Vec3& pb : b)
          clear = clear || caster.segmentClear(pa, pb, world::kLinkClearanceTolerance);
      links.setLinked(i, j, clear);
    }
  return links;
}

}  // namespace coinspect::comms::test
