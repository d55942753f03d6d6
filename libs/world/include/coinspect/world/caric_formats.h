// Readers for the reference CARIC benchmark's files (caric-reference.md).
#pragma once

#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "coinspect/world/fleet.h"
#include "coinspect/world/interest_points.h"
#include "coinspect/world/oriented_box.h"

namespace coinspect::world {

// PCD v0.7 "DATA binary" with fields normal_x normal_y normal_z x y z _ (28-byte records);
// trailing zero padding after the last record is ignored. Errors name the file and, for data,
// the byte offset.
std::vector<InterestPoint> readCaricInterestPoints(const std::filesystem::path& path);
// Writes the same format (no trailing padding); readCaricInterestPoints reads it back exactly.
void writeCaricInterestPoints(const std::vector<InterestPoint>& points,
                              const std::filesystem::path& path);

// box_description.yaml: per box `center`, `size` and a 4x4 row-major `orientation` whose 3x3
// rotation block is used and whose translation column is ignored. Errors name file and line.
// The block is the box-to-world rotation (its columns are the box axes in the world frame, as
// OrientedBox::rotation): checked against the MBS data, where every interest point then lies
// inside a box, while with the transpose 772 of the 3973 lie outside. Blocks orthonormal within
// 1e-3 (the file has ~1e-5) are projected onto the nearest rotation.
std::vector<OrientedBox> readCaricBoxes(const std::filesystem::path& path);

// One row of caric_ppcom_network_*.txt.
struct CaricNetworkUnit {
  std::string name;
  std::string role;  // "manager" or "peer"
  double antennaOffset = 0.1;
  CameraSpec camera;
};
// 16 comma-separated fields per line, whitespace stripped, '#' comments; errors name file and
// line (wrong field count, non-numeric field).
std::vector<CaricNetworkUnit> readCaricNetwork(const std::filesystem::path& path);

// Start positions from a CARIC launch file (run_*.launch): per unit name (the include's
// `namespace` argument), the spawn `x`/`y`/`z` (ground station) or `start_x`/`start_y`/`start_z`
// (UAVs). A missing z is 0.1 m (spawn_uav.launch's default), a missing yaw (`yaw`/`start_yaw`,
// radians) is 0. Errors name the file and line (non-numeric or non-finite value).
struct CaricStartPose {
  Vec3 position = Vec3::Zero();
  double yaw = 0.0;
  std::string role;  // the include's `role` argument ("explorer", "photographer"), empty if none
};
std::map<std::string, CaricStartPose> readCaricStartPoses(const std::filesystem::path& path);

}  // namespace coinspect::world
