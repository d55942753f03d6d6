// Trajectories in the TUM RGB-D benchmark format, one file per unit: one line per pose,
// "timestamp tx ty tz qx qy qz qw", space separated, readable by evo and the TUM tools.
#pragma once

#include <filesystem>
#include <fstream>
#include <vector>

#include "coinspect/world/mesh.h"

namespace coinspect::record {

struct TumPose {
  double time = 0.0;  // s
  world::Vec3 position = world::Vec3::Zero();
  double qx = 0.0, qy = 0.0, qz = 0.0, qw = 1.0;
};

// The unit quaternion of the ZYX (yaw-pitch-roll) attitude R = Rz(yaw) Ry(pitch) Rx(roll),
// with qw >= 0 so that every attitude has one spelling.
TumPose tumPose(double time, const world::Vec3& position, double yaw, double pitch, double roll);

// Appends poses to a file. Formatting is fixed (time and position to 1e-6, quaternion to 1e-9)
// so equal runs give equal files. Movable, not copyable (it owns the stream).
class TumTrajectoryWriter {
 public:
  // Creates or truncates the file; throws InputError if it cannot be written.
  explicit TumTrajectoryWriter(const std::filesystem::path& path);
  TumTrajectoryWriter(TumTrajectoryWriter&&) = default;
  TumTrajectoryWriter& operator=(TumTrajectoryWriter&&) = default;

  void append(double time, const world::Vec3& position, double yaw, double pitch, double roll);
  void append(const TumPose& pose);
  // Flushes; throws InputError if any write failed.
  void close();
  size_t size() const { return count_; }

 private:
  std::filesystem::path path_;
  std::ofstream out_;
  size_t count_ = 0;
};

// Reads a TUM file ('#' comment lines and blank lines skipped); throws InputError naming the
// file and line for a line that is not 8 finite numbers.
std::vector<TumPose> readTumTrajectory(const std::filesystem::path& path);

}  // namespace coinspect::record
