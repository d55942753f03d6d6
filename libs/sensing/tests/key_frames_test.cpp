// Key frame selection (CARIC's rule) and voxel downsampling on hand-made poses and clouds.
#include "coinspect/sensing/key_frames.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace coinspect::sensing {
namespace {

constexpr double kDeg = M_PI / 180.0;

Eigen::Isometry3d bodyAt(double x, double y, double headingDeg, double rollDeg = 0.0) {
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.translation() = Eigen::Vector3d(x, y, 5.0);
  pose.linear() = (Eigen::AngleAxisd(headingDeg * kDeg, Eigen::Vector3d::UnitZ()) *
                   Eigen::AngleAxisd(rollDeg * kDeg, Eigen::Vector3d::UnitX()))
                      .toRotationMatrix();
  return pose;
}

LidarScan scanAt(double time) {
  LidarScan scan;
  scan.time = time;
  return scan;
}

TEST(VoxelDownsample, KeepsOnePointPerVoxelNearestItsCentre) {
  // A 4 x 4 x 4 lattice 0.25 m apart from 0.125: each 0.5 m voxel holds 8 points.
  std::vector<Eigen::Vector3f> lattice;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j)
      for (int k = 0; k < 4; ++k)
        lattice.emplace_back(0.125f + 0.25f * i, 0.125f + 0.25f * j, 0.125f + 0.25f * k);
  EXPECT_EQ(voxelDownsample(lattice, 0.5).size(), 8u);
  EXPECT_EQ(voxelDownsample(lattice, 1.0).size(), 1u);
  EXPECT_EQ(voxelDownsample(lattice, 0.25).size(), 64u);

  // Voxel [0, 0.5)^3 has centre (0.25, 0.25, 0.25): (0.3, 0.3, 0.3) is nearer than (0.1, ...).
  // Voxel boundaries at 0: -0.1 and 0.1 are in different voxels. Output in voxel order.
  const std::vector<Eigen::Vector3f> cloud = {
      {0.6f, 0.1f, 0.1f}, {0.1f, 0.1f, 0.1f}, {0.3f, 0.3f, 0.3f}, {-0.1f, 0.1f, 0.1f}};
  const auto kept = voxelDownsample(cloud, 0.5);
  ASSERT_EQ(kept.size(), 3u);
  EXPECT_EQ(kept[0], Eigen::Vector3f(-0.1f, 0.1f, 0.1f));
  EXPECT_EQ(kept[1], Eigen::Vector3f(0.3f, 0.3f, 0.3f));
  EXPECT_EQ(kept[2], Eigen::Vector3f(0.6f, 0.1f, 0.1f));

  // Two points equally far from the centre (0.5, 0.5, 0.5): the first in input order stays.
  const auto one = voxelDownsample({{0.5f, 0.75f, 0.5f}, {0.5f, 0.25f, 0.5f}}, 1.0);
  ASSERT_EQ(one.size(), 1u);
  EXPECT_EQ(one[0], Eigen::Vector3f(0.5f, 0.75f, 0.5f));
  // x = 0.5 starts the next voxel.
  EXPECT_EQ(voxelDownsample({{0.5f, 0.25f, 0.25f}, {0.0f, 0.25f, 0.25f}}, 0.5).size(), 2u);
  EXPECT_TRUE(voxelDownsample({}, 0.5).empty());
}

TEST(KeyFrames, FirstScanThenOnlyAfterOneSecondAndTwoMetres) {
  KeyFrameSelector selector;
  EXPECT_TRUE(selector.offer(scanAt(0.0), bodyAt(0, 0, 0)));
  // Far away but too soon (the interval is strict).
  EXPECT_FALSE(selector.offer(scanAt(0.5), bodyAt(10, 0, 0)));
  EXPECT_FALSE(selector.offer(scanAt(1.0), bodyAt(10, 0, 0)));
  // Late enough but neither 2 m away nor 10 deg turned.
  EXPECT_FALSE(selector.offer(scanAt(1.5), bodyAt(1.9, 0, 5)));
  EXPECT_TRUE(selector.offer(scanAt(1.6), bodyAt(2.1, 0, 0)));
  ASSERT_EQ(selector.keyFrames().size(), 2u);
  EXPECT_EQ(selector.keyFrames()[1].id, 1u);
  EXPECT_DOUBLE_EQ(selector.keyFrames()[1].time, 1.6);
  // 2.1 m from the first but only 1.05 m from the second.
  EXPECT_FALSE(selector.offer(scanAt(3.0), bodyAt(1.05, 0, 0)));
}

TEST(KeyFrames, TurningTenDegreesFromEveryNearNeighbourMakesAKeyFrame) {
  KeyFrameSelector selector;
  EXPECT_TRUE(selector.offer(scanAt(0.0), bodyAt(0, 0, 0)));
  EXPECT_TRUE(selector.offer(scanAt(2.0), bodyAt(3, 0, 0)));
  EXPECT_FALSE(selector.offer(scanAt(4.0), bodyAt(1.5, 0, 9)));
  EXPECT_TRUE(selector.offer(scanAt(4.5), bodyAt(1.5, 0, 15)));
  // Within 10 deg of the one just added; then 15 deg from it and 30 deg from the others.
  EXPECT_FALSE(selector.offer(scanAt(6.0), bodyAt(1.5, 0, 20)));
  EXPECT_TRUE(selector.offer(scanAt(6.0), bodyAt(1.5, 0, 30)));
  // Headings wrap: 355 deg is 5 deg from 0, and roll or pitch do not count.
  KeyFrameSelector wrap;
  EXPECT_TRUE(wrap.offer(scanAt(0.0), bodyAt(0, 0, 0)));
  EXPECT_FALSE(wrap.offer(scanAt(2.0), bodyAt(0, 0, 355)));
  EXPECT_FALSE(wrap.offer(scanAt(2.0), bodyAt(0, 0, 0, 40)));
  EXPECT_TRUE(wrap.offer(scanAt(2.0), bodyAt(0, 0, -12)));
  EXPECT_NEAR(wrap.keyFrames()[1].pose.linear().col(0).y(), std::sin(-12 * kDeg), 1e-12);
}

TEST(KeyFrames, OnlyTheFiveNearestKeyFramesAreCompared) {
  const auto build = [](size_t neighbours) {
    KeyFrameRule rule;
    rule.neighbours = neighbours;
    KeyFrameSelector selector(rule);
    EXPECT_TRUE(selector.offer(scanAt(0.0), bodyAt(0, 0, 0)));
    // Five key frames at one place 20 deg apart in heading, 10 m from the first.
    for (int i = 1; i <= 5; ++i)
      EXPECT_TRUE(selector.offer(scanAt(2.0 * i), bodyAt(10, 0, 20.0 * i)));
    return selector;
  };
  // Heading 0 at (10, 0): its 5 nearest differ by >= 20 deg; the first (same heading) is 6th.
  auto five = build(5);
  EXPECT_TRUE(five.offer(scanAt(20.0), bodyAt(10, 0, 0)));
  auto six = build(6);
  EXPECT_FALSE(six.offer(scanAt(20.0), bodyAt(10, 0, 0)));
}

TEST(KeyFrames, CloudGoesToTheWorldFrameDownsampled) {
  KeyFrameSelector selector;
  LidarScan scan = scanAt(0.0);
  scan.sensorPose.translation() = Eigen::Vector3d(10.0, 0.0, 0.0);
  scan.points = {{0.1f, 0.1f, 0.1f}, {0.3f, 0.3f, 0.3f}, {1.1f, 0.1f, 0.1f}};
  ASSERT_TRUE(selector.offer(scan, bodyAt(10, 0, 0)));
  const auto& points = selector.keyFrames()[0].points;
  // World (10.1, ...) and (10.3, ...) share the voxel centred at (10.25, 0.25, 0.25).
  ASSERT_EQ(points.size(), 2u);
  EXPECT_TRUE(points[0].isApprox(Eigen::Vector3f(10.3f, 0.3f, 0.3f)));
  EXPECT_TRUE(points[1].isApprox(Eigen::Vector3f(11.1f, 0.1f, 0.1f)));
}

}  // namespace
}  // namespace coinspect::sensing
