// The simulated LiDAR against a box room whose wall distances are known exactly.
#include "coinspect/sensing/lidar.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "lidar_scenes.h"

namespace coinspect::sensing {
namespace {

using test::boxRoom;
using test::kRoomMax;
using test::kRoomMin;
using test::roomDistance;
using test::vlp16;

constexpr double kDeg = M_PI / 180.0;
// Embree intersects in float: a few ulps of 20 m.
constexpr double kRangeTolerance = 1e-3;

world::RayCaster roomCaster() {
  return world::RayCaster({boxRoom()}, std::nullopt);
}

Eigen::Isometry3d poseAt(const Eigen::Vector3d& position, double yaw, double pitch, double roll) {
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.translation() = position;
  pose.linear() = (Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()) *
                   Eigen::AngleAxisd(pitch, Eigen::Vector3d::UnitY()) *
                   Eigen::AngleAxisd(roll, Eigen::Vector3d::UnitX()))
                      .toRotationMatrix();
  return pose;
}

TEST(LidarGeometry, ChannelElevationsAndColumnAzimuthsFollowTheSpec) {
  const LidarSpec spec = vlp16();
  const LidarSimulator lidar(spec, 1);
  ASSERT_EQ(lidar.directions().size(), 16u * 440u);
  for (int column = 0; column < 440; ++column)
    for (int channel = 0; channel < 16; ++channel) {
      // 16 channels every 2 deg from -15; 440 columns from -180 to +180 inclusive (Gazebo's
      // spacing: 360 / 439 deg).
      const double elevation = (-15.0 + 2.0 * channel) * kDeg;
      const double azimuth = (-180.0 + 360.0 * column / 439.0) * kDeg;
      const Eigen::Vector3d& d = lidar.directions()[static_cast<size_t>(column * 16 + channel)];
      EXPECT_NEAR(d.norm(), 1.0, 1e-12);
      EXPECT_NEAR(std::asin(d.z()), elevation, 1e-12);
      if (column > 0 && column < 439) {
        EXPECT_NEAR(std::atan2(d.y(), d.x()), azimuth, 1e-12);
      }
    }
  // Both ends of the revolution are sampled, so they coincide.
  EXPECT_NEAR(std::abs(std::atan2(lidar.directions()[0].y(), lidar.directions()[0].x())), M_PI,
              1e-12);
  EXPECT_TRUE(lidar.directions()[0].isApprox(lidar.directions()[439 * 16], 1e-12));
}

TEST(LidarSweep, EveryRangeEqualsTheAnalyticWallDistance) {
  const auto caster = roomCaster();
  LidarSimulator lidar(vlp16(), 1);
  const Eigen::Isometry3d pose = poseAt({7.0, 4.0, 2.5}, 30 * kDeg, -5 * kDeg, 10 * kDeg);
  LidarScan scan;
  lidar.sweep(caster, pose, scan);
  // Every wall is between 2.5 m and 23 m away: all 7040 rays return, in ray order.
  ASSERT_EQ(scan.points.size(), lidar.directions().size());
  EXPECT_TRUE(scan.sensorPose.isApprox(pose));
  for (size_t i = 0; i < scan.points.size(); ++i) {
    const Eigen::Vector3d p = scan.points[i].cast<double>();
    const Eigen::Vector3d worldDirection = pose.linear() * lidar.directions()[i];
    EXPECT_NEAR(p.norm(), roomDistance(pose.translation(), worldDirection), kRangeTolerance) << i;
    EXPECT_NEAR(p.normalized().dot(lidar.directions()[i]), 1.0, 1e-9) << i;
    // In the world the point lies on a wall: one coordinate is at a bound.
    const Eigen::Vector3d w = pose * p;
    const double toWall =
        std::min((w - kRoomMin).cwiseAbs().minCoeff(), (w - kRoomMax).cwiseAbs().minCoeff());
    EXPECT_LT(toWall, kRangeTolerance) << i;
  }
}

// Counts the rays whose exact distance lies in (low, high), shrunk or widened by a margin so that
// float rounding near a threshold cannot flip the expectation.
size_t countInBand(const LidarSimulator& lidar, const Eigen::Isometry3d& pose, double low,
                   double high, double margin) {
  size_t count = 0;
  for (const auto& d : lidar.directions()) {
    const double r = roomDistance(pose.translation(), pose.linear() * d);
    count += (low + margin < r && r < high - margin) ? 1 : 0;
  }
  return count;
}

TEST(LidarSweep, KeepsOnlyReturnsStrictlyInsideTheRangeBand) {
  const auto caster = roomCaster();
  LidarSpec spec = vlp16();
  spec.minRange = 0.9;
  spec.maxRange = 8.0;
  LidarSimulator lidar(spec, 1);
  // 0.5 m from the x = 0 wall: the rays towards it end before min range; the far walls are
  // beyond max range.
  const Eigen::Isometry3d pose = poseAt({0.5, 5.0, 3.0}, 0.2, 0.0, 0.0);
  LidarScan scan;
  lidar.sweep(caster, pose, scan);
  EXPECT_GE(scan.points.size(), countInBand(lidar, pose, 0.9, 8.0, kRangeTolerance));
  EXPECT_LE(scan.points.size(), countInBand(lidar, pose, 0.9, 8.0, -kRangeTolerance));
  EXPECT_GT(scan.points.size(), 0u);
  EXPECT_LT(scan.points.size(), lidar.directions().size() / 2);
  for (const auto& p : scan.points) {
    EXPECT_GT(p.norm(), 0.9f);
    EXPECT_LT(p.norm(), 8.0f);
  }
}

TEST(LidarSweep, RangeNoiseHasTheSpecifiedSigmaAndIsSeeded) {
  const auto caster = roomCaster();
  LidarSpec spec = vlp16();
  spec.rangeNoiseSigma = 0.05;
  const Eigen::Isometry3d pose = poseAt({10.0, 5.0, 3.0}, 0.3, 0.0, 0.0);
  LidarSimulator lidar(spec, 42);
  LidarScan scan;
  lidar.sweep(caster, pose, scan);
  ASSERT_EQ(scan.points.size(), lidar.directions().size());  // walls >= 3 m away: none leave
  double sum = 0.0, sumSquares = 0.0;
  for (size_t i = 0; i < scan.points.size(); ++i) {
    const double error = scan.points[i].cast<double>().norm() -
                         roomDistance(pose.translation(), pose.linear() * lidar.directions()[i]);
    sum += error;
    sumSquares += error * error;
  }
  const double n = static_cast<double>(scan.points.size());
  const double mean = sum / n;
  const double sigma = std::sqrt(sumSquares / n - mean * mean);
  // Standard errors for n = 7040: mean 0.05 / sqrt(n) = 0.0006, sigma about 0.05 / sqrt(2n).
  EXPECT_LT(std::abs(mean), 4.0 * 0.05 / std::sqrt(n));
  EXPECT_NEAR(sigma, 0.05, 4.0 * 0.05 / std::sqrt(2.0 * n));

  LidarSimulator same(spec, 42), other(spec, 43);
  LidarScan again, different;
  same.sweep(caster, pose, again);
  other.sweep(caster, pose, different);
  EXPECT_EQ(again.points, scan.points);
  EXPECT_NE(different.points, scan.points);
}

TEST(LidarSweep, NoiselessSweepsAreIdenticalAcrossSimulators) {
  const auto caster = roomCaster();
  LidarSimulator a(vlp16(), 1), b(vlp16(), 99);
  const Eigen::Isometry3d pose = poseAt({3.0, 2.0, 1.5}, 1.0, 0.2, -0.1);
  LidarScan first, second;
  a.sweep(caster, pose, first);
  b.sweep(caster, pose, second);
  EXPECT_EQ(first.points, second.points);
}

TEST(LidarSweep, SphereOccludersStopRaysAtTheirSurface) {
  const auto caster = roomCaster();
  LidarSimulator lidar(vlp16(), 1);
  const Eigen::Isometry3d pose = poseAt({5.0, 5.0, 3.0}, 0.0, 0.0, 0.0);
  // A 0.5 m sphere 4 m ahead on the sensor's x axis, where the +-1 deg channels look.
  const SphereOccluder uav{{9.0, 5.0, 3.0}, 0.5};
  LidarScan scan;
  lidar.sweep(caster, pose, scan, {uav});
  ASSERT_EQ(scan.points.size(), lidar.directions().size());
  size_t blocked = 0;
  for (size_t i = 0; i < scan.points.size(); ++i) {
    const Eigen::Vector3d& d = lidar.directions()[i];
    const double wall = roomDistance(pose.translation(), d);
    const double sphere = raySphereDistance(pose.translation(), d, uav);
    EXPECT_NEAR(scan.points[i].norm(), std::min(wall, sphere), kRangeTolerance) << i;
    blocked += sphere < wall ? 1 : 0;
  }
  EXPECT_GT(blocked, 0u);
  // The ray straight at the centre stops 0.5 m short of it.
  EXPECT_NEAR(raySphereDistance({5, 5, 3}, {1, 0, 0}, uav), 3.5, 1e-12);
}

TEST(LidarTilt, ServoFollowsTheReferenceProfile) {
  LidarSpec spec = vlp16();
  spec.tiltAmplitude = 90 * kDeg;
  spec.tiltPeriod = 8.0;
  spec.sensorOffset = Eigen::Vector3d(0.0, 0.0, 0.00185);
  // Rate 2 pi / 8 = 45 deg/s, upwards for 4 s (stopping at +90 after 2 s), then alternating.
  EXPECT_DOUBLE_EQ(servoTiltAngle(spec, 0.0), 0.0);
  EXPECT_NEAR(servoTiltAngle(spec, 1.0), 45 * kDeg, 1e-12);
  EXPECT_NEAR(servoTiltAngle(spec, 2.0), 90 * kDeg, 1e-12);  // period / 4
  EXPECT_NEAR(servoTiltAngle(spec, 3.0), 90 * kDeg, 1e-12);
  EXPECT_NEAR(servoTiltAngle(spec, 6.0), 0.0, 1e-12);
  EXPECT_NEAR(servoTiltAngle(spec, 8.0), -90 * kDeg, 1e-12);
  EXPECT_NEAR(servoTiltAngle(spec, 9.0), -45 * kDeg, 1e-12);
  EXPECT_NEAR(servoTiltAngle(spec, 12.0), 90 * kDeg, 1e-12);
  EXPECT_NEAR(servoTiltAngle(spec, 1000.0 + 2.0), 0.0, 1e-9);  // 1002 = 4 + 124 * 8 + 6

  const Eigen::Isometry3d atZero = lidarPoseInBody(spec, 0.0);
  EXPECT_TRUE(atZero.linear().isIdentity(1e-12));
  EXPECT_TRUE(atZero.translation().isApprox(Eigen::Vector3d(0, 0, 0.20185), 1e-12));
  // At +90 deg about body x the spin axis (sensor z) points along body -y.
  const Eigen::Isometry3d atQuarter = lidarPoseInBody(spec, 2.0);
  EXPECT_TRUE(atQuarter.linear().col(2).isApprox(Eigen::Vector3d(0, -1, 0), 1e-12));
  EXPECT_TRUE(atQuarter.linear().col(0).isApprox(Eigen::Vector3d(1, 0, 0), 1e-12));
  EXPECT_TRUE(atQuarter.translation().isApprox(Eigen::Vector3d(0, -0.00185, 0.2), 1e-12));

  const LidarSpec fixed = vlp16();
  EXPECT_DOUBLE_EQ(servoTiltAngle(fixed, 3.0), 0.0);
}

TEST(LidarTilt, SweepFromBodyComposesTheMountWithTheBodyPose) {
  const auto caster = roomCaster();
  LidarSpec spec = vlp16();
  spec.tiltAmplitude = 90 * kDeg;
  spec.tiltPeriod = 8.0;
  LidarSimulator lidar(spec, 1);
  const Eigen::Isometry3d body = poseAt({8.0, 5.0, 2.0}, 0.5, 0.0, 0.0);
  LidarScan scan;
  lidar.sweepFromBody(caster, 1.0, body, scan);
  EXPECT_DOUBLE_EQ(scan.time, 1.0);
  EXPECT_TRUE(scan.sensorPoseInBody.isApprox(lidarPoseInBody(spec, 1.0)));
  EXPECT_TRUE(scan.sensorPose.isApprox(body * lidarPoseInBody(spec, 1.0)));
  ASSERT_EQ(scan.points.size(), lidar.directions().size());
  for (size_t i = 0; i < scan.points.size(); i += 97) {
    const Eigen::Vector3d d = scan.sensorPose.linear() * lidar.directions()[i];
    EXPECT_NEAR(scan.points[i].norm(), roomDistance(scan.sensorPose.translation(), d),
                kRangeTolerance);
  }
}

}  // namespace
}  // namespace coinspect::sensing
