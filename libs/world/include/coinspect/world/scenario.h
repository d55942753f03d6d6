// A scenario: the constant model of a mission (geometry, boxes, interest points, fleet).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "coinspect/world/fleet.h"
#include "coinspect/world/interest_points.h"
#include "coinspect/world/mesh.h"
#include "coinspect/world/oriented_box.h"

namespace coinspect::world {

struct Scenario {
  std::string name;
  std::string description;
  std::vector<TriangleMesh> meshes;
  std::vector<OrientedBox> boxes;
  InterestPointSet interestPoints;
  std::vector<UnitSpec> fleet;
  double groundZ = 0.0;
  double missionBudget = 600.0;  // s

  size_t triangleCount() const;
  Aabb bounds() const;  // of the meshes
  // FNV-1a 64 over the geometry, boxes, points and fleet, in a fixed byte order: identifies the
  // scenario in run headers (same content => same hash on every machine). Meshes enter as
  // triangle soups (independent of vertex indexing), every real number rounded to float32; the
  // scenario name, description and mesh/box names are excluded (doc/config.md, "Content hash"),
  // so loadScenario(saveScenario(s)) keeps the hash.
  uint64_t contentHash() const;
};

// Runs every validate* function over the parts; throws InputError naming `source`.
void validateScenario(const Scenario& scenario, const std::string& source);

}  // namespace coinspect::world
