// A closed box room for the LiDAR tests, and the exact distance from inside it to its walls.
#pragma once

#include <Eigen/Core>

#include <algorithm>
#include <limits>

#include "coinspect/sensing/lidar_model.h"
#include "coinspect/world/mesh.h"

namespace coinspect::sensing::test {

// The room [0, 20] x [0, 10] x [0, 6] m: 8 corners, 12 triangles.
inline const Eigen::Vector3d kRoomMin(0.0, 0.0, 0.0);
inline const Eigen::Vector3d kRoomMax(20.0, 10.0, 6.0);

inline world::TriangleMesh boxRoom() {
  world::TriangleMesh mesh;
  mesh.name = "room";
  for (int i = 0; i < 8; ++i)
    mesh.vertices.emplace_back(static_cast<float>(i & 1 ? kRoomMax.x() : kRoomMin.x()),
                               static_cast<float>(i & 2 ? kRoomMax.y() : kRoomMin.y()),
                               static_cast<float>(i & 4 ? kRoomMax.z() : kRoomMin.z()));
  // Corner i has bit 0 = x, bit 1 = y, bit 2 = z; each face is two triangles.
  mesh.triangles = {{0, 2, 1}, {1, 2, 3}, {4, 5, 6}, {5, 7, 6},   // z = min, z = max
                    {0, 1, 4}, {1, 5, 4}, {2, 6, 3}, {3, 6, 7},   // y = min, y = max
                    {0, 4, 2}, {2, 4, 6}, {1, 3, 5}, {3, 7, 5}};  // x = min, x = max
  return mesh;
}

// Distance from `origin` (inside the room) along the unit `direction` to the first wall plane:
// along each axis the ray leaves through the bound it moves towards.
inline double roomDistance(const Eigen::Vector3d& origin, const Eigen::Vector3d& direction) {
  double t = std::numeric_limits<double>::infinity();
  for (int k = 0; k < 3; ++k) {
    if (direction[k] > 0.0) t = std::min(t, (kRoomMax[k] - origin[k]) / direction[k]);
    if (direction[k] < 0.0) t = std::min(t, (kRoomMin[k] - origin[k]) / direction[k]);
  }
  return t;
}

// The reference VLP-16 (the share/coinspect/lidars.ini [vlp16] values, fixed mount).
inline LidarSpec vlp16() {
  LidarSpec spec;
  spec.name = "vlp16";
  spec.mountOffset = Eigen::Vector3d(0.0, 0.0, 0.2);
  return spec;
}

}  // namespace coinspect::sensing::test
