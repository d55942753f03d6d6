#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <cmath>

#include "coinspect/strategies/runtime/box_geometry.h"
#include "test_boxes.h"

namespace coinspect::strategies::runtime {
namespace {

using test::makeBox;

TEST(BoxGeometry, BoundsOfARotatedBoxAndTheMissionRegion) {
  const auto box = makeBox({0, 0, 5}, {2, 2, 10}, M_PI / 4);
  const Aabb bounds = boxBounds(box);
  EXPECT_NEAR(bounds.max.x(), std::sqrt(2.0), 1e-12);
  EXPECT_NEAR(bounds.min.z(), 0.0, 1e-12);
  const Aabb region = missionRegion({box, makeBox({10, 0, 20}, {2, 2, 2})}, 3.0, -1.0);
  EXPECT_NEAR(region.min.x(), -std::sqrt(2.0) - 3.0, 1e-12);
  EXPECT_NEAR(region.max.x(), 14.0, 1e-12);
  EXPECT_NEAR(region.min.z(), -1.0, 1e-12);  // from the ground, no margin below it
  EXPECT_NEAR(region.max.z(), 24.0, 1e-12);
}

TEST(BoxGeometry, SplitsAlongTheLongestSide) {
  const auto box = makeBox({0, 0, 0}, {4, 12, 2}, M_PI / 2);  // long edge along world -x
  EXPECT_EQ(longestAxis(box), 1);
  const auto parts = splitBox(box, 3);
  ASSERT_EQ(parts.size(), 3u);
  double volume = 0.0;
  for (const auto& part : parts) {
    EXPECT_NEAR(part.size.y(), 4.0, 1e-12);
    EXPECT_NEAR(part.size.x(), 4.0, 1e-12);
    volume += part.size.prod();
  }
  EXPECT_NEAR(volume, box.size.prod(), 1e-9);
  // In order along the box's y axis, which points along world -x.
  EXPECT_NEAR(parts[0].center.x(), 4.0, 1e-12);
  EXPECT_NEAR(parts[2].center.x(), -4.0, 1e-12);
  const auto [first, rest] = cutBox(box, 0.25);
  EXPECT_NEAR(first.size.y(), 3.0, 1e-12);
  EXPECT_NEAR(rest.size.y(), 9.0, 1e-12);
  EXPECT_NEAR((first.center - Vec3(4.5, 0, 0)).norm(), 0.0, 1e-12);
}

TEST(BoxGeometry, LayersSliceTheHeightAndRespectTheFloor) {
  const auto box = makeBox({0, 0, 10}, {5, 5, 20});
  const auto layers = boxLayers(box, 6.0, 0.0);  // 4 layers of 5 m
  ASSERT_EQ(layers.size(), 4u);
  EXPECT_NEAR(layers[0], 2.5, 1e-12);
  EXPECT_NEAR(layers[3], 17.5, 1e-12);
  const auto raised = boxLayers(box, 6.0, 8.0);  // 2.5 and 7.5 both become 8
  ASSERT_EQ(raised.size(), 3u);
  EXPECT_NEAR(raised[0], 8.0, 1e-12);
}

TEST(BoxGeometry, StandoffOrbitKeepsItsDistanceAndStartsNearTheGivenPoint) {
  const auto box = makeBox({5, -3, 10}, {10, 6, 20}, 0.3);
  const double distance = 7.0;
  const auto orbit = standoffOrbit(box, 12.0, distance, 1.0, Vec3(5, -30, 0));
  const double perimeter = footprintOf(box).perimeterAt(distance);
  EXPECT_EQ(orbit.size(), static_cast<size_t>(std::ceil(perimeter / 1.0)));
  for (const auto& p : orbit) {
    EXPECT_NEAR(p.z(), 12.0, 1e-12);
    EXPECT_NEAR(distanceToBox(box, p), distance, 1e-9);  // z inside the box: horizontal distance
  }
  // Counter-clockwise seen from above: the signed area is positive.
  double area = 0.0;
  for (size_t i = 0; i < orbit.size(); ++i) {
    const auto& a = orbit[i];
    const auto& b = orbit[(i + 1) % orbit.size()];
    area += a.x() * b.y() - b.x() * a.y();
  }
  EXPECT_GT(area, 0.0);
  // The first point is the one nearest (5, -30) horizontally.
  for (const auto& p : orbit)
    EXPECT_LE((orbit.front() - Vec3(5, -30, 12)).head<2>().norm(),
              (p - Vec3(5, -30, 12)).head<2>().norm() + 1e-12);
}

TEST(BoxGeometry, ExtendsToTheGroundAndListsFaces) {
  const auto box = makeBox({0, 0, 30}, {4, 6, 10});
  const auto column = extendToGround(box, 0.0);
  EXPECT_NEAR(boxBounds(column).min.z(), 0.0, 1e-12);
  EXPECT_NEAR(boxBounds(column).max.z(), 35.0, 1e-12);
  const auto faces = boxFaces(box);
  ASSERT_EQ(faces.size(), 6u);
  double area = 0.0;
  for (const auto& face : faces) {
    area += face.area();
    EXPECT_NEAR(distanceToBox(box, face.centre + face.normal), 1.0, 1e-12);  // outward
  }
  EXPECT_NEAR(area, 2 * (4 * 6 + 4 * 10 + 6 * 10), 1e-9);
  EXPECT_NEAR((closestPointOnBox(box, Vec3(10, 0, 30)) - Vec3(2, 0, 30)).norm(), 0.0, 1e-12);
}

}  // namespace
}  // namespace coinspect::strategies::runtime
