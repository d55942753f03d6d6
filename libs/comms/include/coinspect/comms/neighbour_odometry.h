// What a unit learns of the others' motion: in the reference each UAV sees the odometry of the
// units in line of sight, and nothing of the rest.
#pragma once

#include <Eigen/Geometry>

#include <cstdint>
#include <vector>

#include "coinspect/comms/link_matrix.h"
#include "coinspect/world/mesh.h"

namespace coinspect::comms {

struct UnitOdometry {
  uint32_t unit = 0;
  double stamp = 0.0;  // simulated seconds
  world::Vec3 position = world::Vec3::Zero();
  world::Vec3 velocity = world::Vec3::Zero();
  Eigen::Quaterniond orientation = Eigen::Quaterniond::Identity();
};

// The entries of `all` (indexed by unit) of the neighbours of `unit` that are alive, in
// increasing unit order; empty when `unit` itself is dead.
std::vector<UnitOdometry> neighbourOdometry(uint32_t unit, const LinkMatrix& links,
                                            const std::vector<bool>& alive,
                                            const std::vector<UnitOdometry>& all);

}  // namespace coinspect::comms
