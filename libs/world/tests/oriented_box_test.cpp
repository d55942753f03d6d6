#include "coinspect/world/oriented_box.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "coinspect/core/error.h"
#include "coinspect/testing/input_errors.h"

namespace coinspect::world {
namespace {

using coinspect::testing::messageOf;

Eigen::Matrix3d rotZ(double degrees) {
  return Eigen::AngleAxisd(degrees * M_PI / 180.0, Vec3::UnitZ()).toRotationMatrix();
}

OrientedBox rotatedBox() {
  OrientedBox box;
  box.name = "tilted";
  box.center = Vec3(1, 2, 3);
  box.size = Vec3(4, 2, 1);
  box.rotation = rotZ(30);
  return box;
}

TEST(OrientedBox, ContainsPointsOfARotatedBox) {
  const OrientedBox box = rotatedBox();
  // Points given in box coordinates, mapped to the world by hand-built rotation.
  EXPECT_TRUE(box.contains(box.center));
  EXPECT_TRUE(box.contains(box.center + box.rotation * Vec3(1.9, 0.9, 0.4)));
  EXPECT_TRUE(box.contains(box.center + box.rotation * Vec3(-1.9, -0.9, -0.4)));
  EXPECT_FALSE(box.contains(box.center + box.rotation * Vec3(2.1, 0, 0)));
  EXPECT_FALSE(box.contains(box.center + box.rotation * Vec3(0, 1.1, 0)));
  EXPECT_FALSE(box.contains(box.center + box.rotation * Vec3(0, 0, 0.6)));
  // (1.9, 0.9, 0) in the world is inside the unrotated box, but in box coordinates it is
  // (1.9 cos30 + 0.9 sin30, -1.9 sin30 + 0.9 cos30, 0) = (2.095, -0.171, 0): outside.
  EXPECT_FALSE(box.contains(box.center + Vec3(1.9, 0.9, 0)));
  const Vec3 local = box.toBox(box.center + Vec3(1.9, 0.9, 0));
  EXPECT_NEAR(local.x(), 1.9 * std::sqrt(3.0) / 2 + 0.45, 1e-12);
  EXPECT_NEAR(local.y(), -0.95 + 0.9 * std::sqrt(3.0) / 2, 1e-12);
  // Along the world y axis, 1.0 from the centre: box coordinates (0.5, 0.866): inside.
  EXPECT_TRUE(box.contains(box.center + Vec3(0, 1.0, 0)));
  // 1.2 along world y: (0.6, 1.039): outside in y.
  EXPECT_FALSE(box.contains(box.center + Vec3(0, 1.2, 0)));
}

TEST(OrientedBox, FacesAreInclusiveAndMarginGrowsEverySide) {
  OrientedBox box;
  box.size = Vec3(2, 4, 6);
  EXPECT_TRUE(box.contains(Vec3(1, 0, 0)));
  EXPECT_TRUE(box.contains(Vec3(-1, -2, -3)));
  EXPECT_TRUE(box.contains(Vec3(1, 2, 3)));
  EXPECT_FALSE(box.contains(Vec3(std::nextafter(1.0, 2.0), 0, 0)));
  EXPECT_FALSE(box.contains(Vec3(0, 0, -3.0001)));

  EXPECT_FALSE(box.contains(Vec3(1.5, 0, 0)));
  EXPECT_TRUE(box.contains(Vec3(1.5, 0, 0), 0.5));
  EXPECT_FALSE(box.contains(Vec3(1.5, 0, 0), 0.49));
  EXPECT_TRUE(box.contains(Vec3(0, -2.25, 3.25), 0.25));
  EXPECT_FALSE(box.contains(Vec3(0, -2.25, 3.5), 0.25));
  EXPECT_DOUBLE_EQ(box.volume(), 48.0);
}

TEST(OrientedBox, VerticesFollowTheReferenceOrder) {
  OrientedBox box;
  box.center = Vec3(10, 20, 30);
  box.size = Vec3(2, 4, 6);
  const auto v = box.vertices();
  const Vec3 expected[8] = {{9, 18, 27}, {11, 18, 27}, {11, 22, 27}, {9, 22, 27},
                            {9, 18, 33}, {11, 18, 33}, {11, 22, 33}, {9, 22, 33}};
  for (int i = 0; i < 8; ++i)
    EXPECT_TRUE(v[i].isApprox(expected[i], 1e-12)) << "vertex " << i;

  // A quarter turn maps box x to world y and box y to world -x: vertex 1 = (+,-,-) in box
  // coordinates = (1, -2, -3) -> world offset (2, 1, -3).
  box.rotation = rotZ(90);
  const auto r = box.vertices();
  EXPECT_TRUE(r[1].isApprox(Vec3(12, 21, 27), 1e-12)) << r[1].transpose();
  EXPECT_TRUE(r[6].isApprox(Vec3(8, 21, 33), 1e-12)) << r[6].transpose();
  for (const Vec3& corner : r)
    EXPECT_TRUE(box.contains(corner, 1e-9));
}

TEST(OrientedBox, ValidateRejectsBadBoxesNamingThem) {
  EXPECT_NO_THROW(validateBox(rotatedBox(), "boxes.yaml"));

  OrientedBox negative = rotatedBox();
  negative.size.y() = -1.0;
  std::string message = messageOf([&] { validateBox(negative, "boxes.yaml"); });
  EXPECT_NE(message.find("boxes.yaml"), std::string::npos) << message;
  EXPECT_NE(message.find("tilted"), std::string::npos) << message;
  EXPECT_NE(message.find("positive"), std::string::npos) << message;

  OrientedBox zero = rotatedBox();
  zero.size.z() = 0.0;
  EXPECT_THROW(validateBox(zero, "x"), InputError);

  OrientedBox nan = rotatedBox();
  nan.center.x() = std::numeric_limits<double>::quiet_NaN();
  message = messageOf([&] { validateBox(nan, "boxes.yaml"); });
  EXPECT_NE(message.find("tilted"), std::string::npos) << message;
  EXPECT_NE(message.find("center"), std::string::npos) << message;

  OrientedBox scaled = rotatedBox();
  scaled.rotation *= 1.1;
  message = messageOf([&] { validateBox(scaled, "boxes.yaml"); });
  EXPECT_NE(message.find("orthonormal"), std::string::npos) << message;

  OrientedBox mirrored = rotatedBox();
  mirrored.rotation.col(2) *= -1.0;
  message = messageOf([&] { validateBox(mirrored, "boxes.yaml"); });
  EXPECT_NE(message.find("determinant"), std::string::npos) << message;
}

}  // namespace
}  // namespace coinspect::world
