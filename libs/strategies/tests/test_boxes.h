// Inspection boxes for the strategies' tests: one helper instead of a copy per test file.
#pragma once

#include <Eigen/Geometry>

#include "coinspect/agent/observations.h"

namespace coinspect::strategies::test {

// A box with `size` (full edges) around `centre`, turned `yaw` rad about the vertical.
inline agent::BoxView makeBox(const agent::Vec3& centre, const agent::Vec3& size,
                              double yaw = 0.0) {
  agent::BoxView box;
  box.center = centre;
  box.size = size;
  box.rotation = Eigen::AngleAxisd(yaw, agent::Vec3::UnitZ()).toRotationMatrix();
  return box;
}

}  // namespace coinspect::strategies::test
