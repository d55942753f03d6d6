// LiDAR scans converted to MRPT observations keep their points, sensor pose, time and label.
#include "coinspect/sensing/lidar_observation.h"

#include <gtest/gtest.h>
#include <mrpt/core/Clock.h>
#include <mrpt/maps/CPointsMap.h>
#include <mrpt/obs/CObservationPointCloud.h>
#include <mrpt/poses/CPose3D.h>

#include <cmath>

namespace coinspect::sensing {
namespace {

TEST(LidarObservation, KeepsPointsSensorPoseTimeAndLabel) {
  LidarSpec spec;
  spec.tiltAmplitude = M_PI / 2.0;
  spec.tiltPeriod = 8.0;
  spec.mountOffset = Eigen::Vector3d(0.0, 0.0, 0.2);
  LidarScan scan;
  scan.time = 12.25;
  scan.sensorPoseInBody = lidarPoseInBody(spec, 1.0);  // 45 deg about body x
  scan.points = {{1.0f, 2.0f, 3.0f}, {-4.5f, 0.25f, 7.0f}, {0.0f, 0.0f, -1.0f}};

  const auto observation = toObservation(scan, "jurong.lidar");
  ASSERT_TRUE(observation);
  EXPECT_EQ(observation->sensorLabel, "jurong.lidar");
  EXPECT_DOUBLE_EQ(mrpt::Clock::toDouble(observation->timestamp), 12.25);
  ASSERT_TRUE(observation->pointcloud);
  ASSERT_EQ(observation->pointcloud->size(), scan.points.size());
  for (size_t i = 0; i < scan.points.size(); ++i) {
    float x = 0, y = 0, z = 0;
    observation->pointcloud->getPoint(i, x, y, z);
    EXPECT_EQ(x, scan.points[i].x());
    EXPECT_EQ(y, scan.points[i].y());
    EXPECT_EQ(z, scan.points[i].z());
  }
  // sensorPose is the sensor in the body: (0, 0, 0.2), roll 45 deg.
  const mrpt::poses::CPose3D& pose = observation->sensorPose;
  EXPECT_NEAR(pose.x(), 0.0, 1e-12);
  EXPECT_NEAR(pose.y(), 0.0, 1e-12);
  EXPECT_NEAR(pose.z(), 0.2, 1e-12);
  EXPECT_NEAR(pose.yaw(), 0.0, 1e-12);
  EXPECT_NEAR(pose.pitch(), 0.0, 1e-12);
  EXPECT_NEAR(pose.roll(), M_PI / 4.0, 1e-12);
}

}  // namespace
}  // namespace coinspect::sensing
