#include "coinspect/sensing/key_frames.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <utility>

#include "coinspect/core/error.h"

namespace coinspect::sensing {

namespace {

using VoxelKey = std::array<int64_t, 3>;

double wrappedAbs(double angle) {
  double wrapped = std::fmod(std::abs(angle), 2.0 * M_PI);
  return wrapped > M_PI ? 2.0 * M_PI - wrapped : wrapped;
}

Eigen::Isometry3d headingPose(const Eigen::Isometry3d& bodyPose) {
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.translation() = bodyPose.translation();
  pose.linear() =
      Eigen::AngleAxisd(headingOf(bodyPose.linear()), Eigen::Vector3d::UnitZ()).toRotationMatrix();
  return pose;
}

}  // namespace

std::vector<Eigen::Vector3f> voxelDownsample(const std::vector<Eigen::Vector3f>& points,
                                             double voxelSize) {
  COINSPECT_ASSERT(voxelSize > 0.0);
  std::vector<std::pair<VoxelKey, size_t>> keyed;
  keyed.reserve(points.size());
  for (size_t i = 0; i < points.size(); ++i) {
    const Eigen::Vector3d p = points[i].cast<double>();
    if (!p.allFinite()) continue;
    keyed.push_back({{static_cast<int64_t>(std::floor(p.x() / voxelSize)),
                      static_cast<int64_t>(std::floor(p.y() / voxelSize)),
                      static_cast<int64_t>(std::floor(p.z() / voxelSize))},
                     i});
  }
  // Sorting (key, index) pairs groups each voxel with its points in input order.
  std::sort(keyed.begin(), keyed.end());
  std::vector<Eigen::Vector3f> kept;
  for (size_t start = 0; start < keyed.size();) {
    const VoxelKey& key = keyed[start].first;
    const Eigen::Vector3d centre =
        (Eigen::Vector3d(key[0], key[1], key[2]) + Eigen::Vector3d::Constant(0.5)) * voxelSize;
    size_t best = keyed[start].second;
    double bestDistance = (points[best].cast<double>() - centre).squaredNorm();
    size_t end = start + 1;
    for (; end < keyed.size() && keyed[end].first == key; ++end) {
      const size_t i = keyed[end].second;
      const double d = (points[i].cast<double>() - centre).squaredNorm();
      if (d < bestDistance) {
        best = i;
        bestDistance = d;
      }
    }
    kept.push_back(points[best]);
    start = end;
  }
  return kept;
}

double headingOf(const Eigen::Matrix3d& rotation) {
  return std::atan2(rotation(1, 0), rotation(0, 0));
}

KeyFrameSelector::KeyFrameSelector(const KeyFrameRule& rule) : rule_(rule) {
  COINSPECT_ASSERT(rule.neighbours >= 1 && rule.voxelSize > 0.0);
}

bool KeyFrameSelector::farFromNeighbours(const Eigen::Isometry3d& pose) const {
  // The k nearest key frames by position, ties to the older one (a linear scan: a mission has
  // at most a few thousand key frames per UAV).
  std::vector<std::pair<double, size_t>> byDistance;
  byDistance.reserve(keyFrames_.size());
  for (size_t i = 0; i < keyFrames_.size(); ++i)
    byDistance.emplace_back((keyFrames_[i].pose.translation() - pose.translation()).squaredNorm(),
                            i);
  const size_t k = std::min(rule_.neighbours, byDistance.size());
  std::partial_sort(byDistance.begin(), byDistance.begin() + static_cast<std::ptrdiff_t>(k),
                    byDistance.end());
  if (byDistance.front().first > rule_.minDistance * rule_.minDistance) return true;
  const double heading = headingOf(pose.linear());
  for (size_t j = 0; j < k; ++j) {
    const double other = headingOf(keyFrames_[byDistance[j].second].pose.linear());
    if (wrappedAbs(heading - other) < rule_.minAngle) return false;
  }
  return true;
}

bool KeyFrameSelector::offer(const LidarScan& scan, const Eigen::Isometry3d& bodyPose) {
  const Eigen::Isometry3d pose = headingPose(bodyPose);
  if (!keyFrames_.empty()) {
    if (!(scan.time - keyFrames_.back().time > rule_.minInterval)) return false;
    if (!farFromNeighbours(pose)) return false;
  }
  KeyFrame frame;
  frame.id = keyFrames_.size();
  frame.time = scan.time;
  frame.pose = pose;
  std::vector<Eigen::Vector3f> world;
  world.reserve(scan.points.size());
  for (const auto& p : scan.points)
    world.push_back((scan.sensorPose * p.cast<double>()).cast<float>());
  frame.points = voxelDownsample(world, rule_.voxelSize);
  keyFrames_.push_back(std::move(frame));
  return true;
}

}  // namespace coinspect::sensing
