// LiDAR key frames as CARIC's mission manager selects them (MissionManager.cpp, doc/sensors.md):
// the first scan is a key frame; a later scan is one when more than minInterval has passed since
// the last key frame AND (the nearest of the k nearest key frames is farther than minDistance OR
// every one of those k differs by at least minAngle in heading). Its cloud goes to the WORLD
// frame and is downsampled on a voxel grid. These are what neighbours in line of sight receive.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <cmath>
#include <cstddef>
#include <vector>

#include "coinspect/sensing/lidar.h"

namespace coinspect::sensing {

struct KeyFrameRule {        // the reference's kf_* parameters (identical in all three scenarios)
  double minInterval = 1.0;  // s, strict
  size_t neighbours = 5;     // kf_knn_num
  double minDistance = 2.0;  // m, kf_min_dis, strict
  double minAngle = 10.0 * M_PI / 180.0;  // rad, kf_min_ang
  double voxelSize = 0.5;                 // m, kf_voxsize
};

struct KeyFrame {
  size_t id = 0;      // 0, 1, 2... in order of selection
  double time = 0.0;  // simulated s
  // Body position with the body's HEADING only (roll and pitch dropped), as the reference keeps
  // it; the angle test compares these rotations, i.e. heading differences.
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  std::vector<Eigen::Vector3f> points;  // the scan in the WORLD frame, voxel-downsampled
};

// One point per occupied voxel (cubes of `voxelSize` aligned with the origin): the input point
// nearest the voxel's centre, the first one on ties (PCL's UniformSampling, which the reference
// uses). Output in ascending (x, y, z) voxel index order, so it is deterministic.
std::vector<Eigen::Vector3f> voxelDownsample(const std::vector<Eigen::Vector3f>& points,
                                             double voxelSize);

// Heading (rad) of a rotation: atan2 of the rotated x axis in the world xy plane.
double headingOf(const Eigen::Matrix3d& rotation);

class KeyFrameSelector {
 public:
  explicit KeyFrameSelector(const KeyFrameRule& rule = {});

  // Offers a scan taken at bodyPose (world); returns true when it became a key frame (then
  // keyFrames().back() is it).
  bool offer(const LidarScan& scan, const Eigen::Isometry3d& bodyPose);

  const std::vector<KeyFrame>& keyFrames() const { return keyFrames_; }
  const KeyFrameRule& rule() const { return rule_; }

 private:
  bool farFromNeighbours(const Eigen::Isometry3d& pose) const;

  KeyFrameRule rule_;
  std::vector<KeyFrame> keyFrames_;
};

}  // namespace coinspect::sensing
