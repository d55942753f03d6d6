#include "coinspect/record/tum_trajectory.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "coinspect/testing/files.h"
#include "coinspect/testing/input_errors.h"

namespace coinspect::record {

namespace {

const double kHalfRoot2 = std::sqrt(0.5);

std::filesystem::path scratch(const std::string& name) {
  const auto folder = std::filesystem::temp_directory_path() / "coinspect_tum_test";
  std::filesystem::create_directories(folder);
  return folder / name;
}

void expectQuaternion(const TumPose& p, double x, double y, double z, double w) {
  EXPECT_NEAR(p.qx, x, 1e-12);
  EXPECT_NEAR(p.qy, y, 1e-12);
  EXPECT_NEAR(p.qz, z, 1e-12);
  EXPECT_NEAR(p.qw, w, 1e-12);
}

}  // namespace

TEST(TumPose, SingleAxisAnglesGiveHalfAngleQuaternions) {
  const world::Vec3 origin = world::Vec3::Zero();
  expectQuaternion(tumPose(0, origin, 0, 0, 0), 0, 0, 0, 1);
  // 90 deg about z: (0, 0, sin 45, cos 45).
  expectQuaternion(tumPose(0, origin, M_PI / 2, 0, 0), 0, 0, kHalfRoot2, kHalfRoot2);
  // 90 deg about y.
  expectQuaternion(tumPose(0, origin, 0, M_PI / 2, 0), 0, kHalfRoot2, 0, kHalfRoot2);
  // 60 deg about x: (sin 30, 0, 0, cos 30).
  expectQuaternion(tumPose(0, origin, 0, 0, M_PI / 3), 0.5, 0, 0, std::sqrt(3.0) / 2);
}

TEST(TumPose, ComposesYawThenPitchThenRoll) {
  // qz(90) qy(90) = (c + s k)(c + s j) = c^2 + cs j + cs k + s^2 kj, kj = -i, c = s = sqrt(1/2):
  // w 0.5, x -0.5, y 0.5, z 0.5.
  expectQuaternion(tumPose(0, world::Vec3::Zero(), M_PI / 2, M_PI / 2, 0), -0.5, 0.5, 0.5, 0.5);
  // Yaw 270 deg: (0, 0, sin 135, cos 135) has w < 0 and is flipped to the spelling of -90 deg.
  expectQuaternion(tumPose(0, world::Vec3::Zero(), 1.5 * M_PI, 0, 0), 0, 0, -kHalfRoot2,
                   kHalfRoot2);
}

TEST(TumTrajectoryWriter, WritesFixedPrecisionLinesThatReadBack) {
  const auto path = scratch("unit.tum");
  {
    TumTrajectoryWriter writer(path);
    writer.append(0.0, {1.0, 2.0, 3.0}, 0.0, 0.0, 0.0);
    writer.append(0.05, {-1.5, 0.25, 10.0}, M_PI / 2, 0.0, 0.0);
    EXPECT_EQ(writer.size(), 2u);
    writer.close();
  }
  EXPECT_EQ(testing::readFile(path),
            "0.000000 1.000000 2.000000 3.000000 0.000000000 0.000000000 0.000000000 "
            "1.000000000\n"
            "0.050000 -1.500000 0.250000 10.000000 0.000000000 0.000000000 0.707106781 "
            "0.707106781\n");
  const auto poses = readTumTrajectory(path);
  ASSERT_EQ(poses.size(), 2u);
  EXPECT_EQ(poses[1].time, 0.05);
  EXPECT_EQ(poses[1].position, world::Vec3(-1.5, 0.25, 10.0));
  EXPECT_NEAR(poses[1].qz, kHalfRoot2, 1e-9);
}

TEST(TumTrajectoryReader, SkipsCommentsAndNamesBadLines) {
  const auto path = scratch("bad.tum");
  testing::writeFile(path, "# timestamp tx ty tz qx qy qz qw\n\n0 0 0 0 0 0 0 1\n0 0 0 0 0 0 1\n");
  const auto message = testing::messageOf([&] { readTumTrajectory(path); });
  EXPECT_MENTIONS(message, "bad.tum");
  EXPECT_MENTIONS(message, "line 4");
}

}  // namespace coinspect::record
