// Something movable that blocks rays but is not part of the static world: another UAV, as a
// sphere of its collision radius. Shared by the camera scorer and the LiDAR.
#pragma once

#include <Eigen/Core>

namespace coinspect::sensing {

struct SphereOccluder {
  Eigen::Vector3d center = Eigen::Vector3d::Zero();  // world frame, m
  double radius = 0.0;                               // m
};

}  // namespace coinspect::sensing
