#include "coinspect/record/tum_trajectory.h"

#include <cmath>
#include <cstdio>
#include <sstream>
#include <string>

#include "coinspect/core/error.h"

namespace coinspect::record {

TumPose tumPose(double time, const world::Vec3& position, double yaw, double pitch, double roll) {
  // Product of the half-angle quaternions qz(yaw) qy(pitch) qx(roll).
  const double cy = std::cos(0.5 * yaw), sy = std::sin(0.5 * yaw);
  const double cp = std::cos(0.5 * pitch), sp = std::sin(0.5 * pitch);
  const double cr = std::cos(0.5 * roll), sr = std::sin(0.5 * roll);
  TumPose pose;
  pose.time = time;
  pose.position = position;
  pose.qw = cr * cp * cy + sr * sp * sy;
  pose.qx = sr * cp * cy - cr * sp * sy;
  pose.qy = cr * sp * cy + sr * cp * sy;
  pose.qz = cr * cp * sy - sr * sp * cy;
  if (pose.qw < 0.0) {
    pose.qw = -pose.qw;
    pose.qx = -pose.qx;
    pose.qy = -pose.qy;
    pose.qz = -pose.qz;
  }
  return pose;
}

TumTrajectoryWriter::TumTrajectoryWriter(const std::filesystem::path& path)
    : path_(path), out_(path, std::ios::binary | std::ios::trunc) {
  if (!out_) throw InputError(path.string(), "open", "cannot write the file");
}

void TumTrajectoryWriter::append(double time, const world::Vec3& position, double yaw, double pitch,
                                 double roll) {
  append(tumPose(time, position, yaw, pitch, roll));
}

void TumTrajectoryWriter::append(const TumPose& pose) {
  char line[256];
  std::snprintf(line, sizeof line, "%.6f %.6f %.6f %.6f %.9f %.9f %.9f %.9f\n", pose.time,
                pose.position.x(), pose.position.y(), pose.position.z(), pose.qx, pose.qy, pose.qz,
                pose.qw);
  out_ << line;
  ++count_;
}

void TumTrajectoryWriter::close() {
  out_.flush();
  if (!out_) throw InputError(path_.string(), "write", "writing the file failed");
  out_.close();
}

std::vector<TumPose> readTumTrajectory(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path.string(), "open", "cannot read the file");
  std::vector<TumPose> poses;
  std::string line;
  for (size_t lineNumber = 1; std::getline(in, line); ++lineNumber) {
    const auto first = line.find_first_not_of(" \t\r");
    if (first == std::string::npos || line[first] == '#') continue;
    std::istringstream fields(line);
    double v[8];
    int count = 0;
    while (count < 8 && fields >> v[count])
      ++count;
    std::string rest;
    fields.clear();
    fields >> rest;
    bool finite = true;
    for (int k = 0; k < count; ++k)
      finite = finite && std::isfinite(v[k]);
    if (count != 8 || !rest.empty() || !finite)
      throw InputError(path.string(), "line " + std::to_string(lineNumber),
                       "expected 8 finite numbers: timestamp tx ty tz qx qy qz qw");
    TumPose pose;
    pose.time = v[0];
    pose.position = world::Vec3(v[1], v[2], v[3]);
    pose.qx = v[4];
    pose.qy = v[5];
    pose.qz = v[6];
    pose.qw = v[7];
    poses.push_back(pose);
  }
  return poses;
}

}  // namespace coinspect::record
