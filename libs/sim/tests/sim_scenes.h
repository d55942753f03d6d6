// Small hand-made scenes for mission tests: a wall with interest points and a few UAVs.
#pragma once

#include <string>

#include "coinspect/world/scenario.h"

namespace coinspect::sim::testing {

// A solid box between `low` and `high` (outward facets).
inline world::TriangleMesh boxMesh(const world::Vec3& low, const world::Vec3& high) {
  world::TriangleMesh mesh;
  mesh.name = "box";
  for (int i = 0; i < 8; ++i)
    mesh.vertices.emplace_back(static_cast<float>(i & 1 ? high.x() : low.x()),
                               static_cast<float>(i & 2 ? high.y() : low.y()),
                               static_cast<float>(i & 4 ? high.z() : low.z()));
  // Two triangles per face, counter-clockwise seen from outside.
  mesh.triangles = {{0, 2, 1}, {1, 2, 3}, {4, 5, 6}, {5, 7, 6}, {0, 1, 4}, {1, 5, 4},
                    {2, 6, 3}, {3, 6, 7}, {0, 4, 2}, {2, 4, 6}, {1, 3, 5}, {3, 7, 5}};
  return mesh;
}

// A unit of the fleet with the default camera, starting at `at`.
inline world::UnitSpec unitAt(const std::string& name, world::UnitRole role,
                              const world::Vec3& at) {
  world::UnitSpec unit;
  unit.name = name;
  unit.role = role;
  unit.startPosition = at;
  return unit;
}

// A wall occupying 10 <= x <= 11, -5 <= y <= 5, 0 <= z <= 10, with interest points every 0.5 m
// on its face x = 10 for |y| <= 2, 3 <= z <= 7 (normal -x). The ground station stands at
// (0, 0, 1); photographers named in `names` start on the ground at (0, y, 0) for the given ys.
inline world::Scenario wallScenario(const std::vector<std::pair<std::string, double>>& uavs) {
  world::Scenario scenario;
  scenario.name = "wall";
  scenario.meshes.push_back(boxMesh({10, -5, 0}, {11, 5, 10}));
  std::vector<world::InterestPoint> points;
  for (int iy = -4; iy <= 4; ++iy)
    for (int iz = 6; iz <= 14; ++iz) {
      world::InterestPoint p;
      p.position = world::Vec3(10.0, 0.5 * iy, 0.5 * iz);
      p.normal = world::Vec3(-1, 0, 0);
      points.push_back(p);
    }
  scenario.interestPoints = world::InterestPointSet(points);
  world::OrientedBox box;
  box.name = "face";
  box.center = world::Vec3(10, 0, 5);
  box.size = world::Vec3(1, 5, 5);
  scenario.boxes.push_back(box);
  scenario.fleet.push_back(unitAt("gcs", world::UnitRole::GroundStation, {0, 0, 1}));
  for (const auto& [name, y] : uavs)
    scenario.fleet.push_back(unitAt(name, world::UnitRole::Photographer, {0, y, 0}));
  scenario.missionBudget = 20.0;
  return scenario;
}

}  // namespace coinspect::sim::testing
