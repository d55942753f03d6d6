#include "coinspect/world/interest_points.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "coinspect/core/error.h"
#include "coinspect/core/random.h"

namespace coinspect::world {
namespace {

std::vector<InterestPoint> randomPoints(Rng& rng, size_t n, double extent) {
  std::vector<InterestPoint> points(n);
  for (auto& p : points)
    p.position = Vec3(rng.uniform(-extent, extent), rng.uniform(-extent, extent),
                      rng.uniform(-extent, extent));
  return points;
}

std::vector<uint32_t> bruteForce(const std::vector<InterestPoint>& points, const Vec3& center,
                                 double radius) {
  std::vector<uint32_t> result;
  for (size_t i = 0; i < points.size(); ++i)
    if ((points[i].position - center).squaredNorm() <= radius * radius)
      result.push_back(static_cast<uint32_t>(i));
  return result;
}

TEST(InterestPointSet, RadiusSearchEqualsBruteForce) {
  Rng rng(20240611);
  for (const size_t n : {1, 7, 300, 2000}) {
    const auto points = randomPoints(rng, n, 10.0);
    const InterestPointSet set(points);
    ASSERT_EQ(set.size(), n);
    size_t nonEmpty = 0;
    for (int query = 0; query < 100; ++query) {
      const Vec3 center(rng.uniform(-12, 12), rng.uniform(-12, 12), rng.uniform(-12, 12));
      const double radius = rng.uniform(0.0, 6.0);
      const auto expected = bruteForce(points, center, radius);
      EXPECT_EQ(set.withinRadius(center, radius), expected) << "n " << n << " query " << query;
      nonEmpty += !expected.empty();
    }
    if (n >= 300) {
      EXPECT_GT(nonEmpty, 50u);  // the comparison is not vacuous
    }
  }
}

TEST(InterestPointSet, BoundaryIsInclusive) {
  std::vector<InterestPoint> points(4);
  points[0].position = Vec3(2, 0, 0);                         // exactly at radius 2
  points[1].position = Vec3(0, -2, 0);                        // exactly at radius 2
  points[2].position = Vec3(0, 0, std::nextafter(2.0, 3.0));  // just outside
  points[3].position = Vec3(1, 1, 1);                         // sqrt(3) < 2
  const InterestPointSet set(points);
  EXPECT_EQ(set.withinRadius(Vec3::Zero(), 2.0), (std::vector<uint32_t>{0, 1, 3}));
  EXPECT_EQ(set.withinRadius(Vec3(2, 0, 0), 0.0), (std::vector<uint32_t>{0}));
  EXPECT_TRUE(set.withinRadius(Vec3::Zero(), 1.7).empty());  // sqrt(3) = 1.732
}

TEST(InterestPointSet, EmptySetAndIndices) {
  const InterestPointSet empty;
  EXPECT_TRUE(empty.empty());
  EXPECT_TRUE(empty.withinRadius(Vec3::Zero(), 100.0).empty());

  std::vector<InterestPoint> points(3);
  for (auto& p : points)
    p.index = 99;
  points[1].position = Vec3(5, 0, 0);
  const InterestPointSet set(points);
  for (uint32_t i = 0; i < 3; ++i)
    EXPECT_EQ(set[i].index, i);
}

TEST(InterestPointSet, NearestNeighbourDistance) {
  std::vector<InterestPoint> points(4);
  points[0].position = Vec3(0, 0, 0);
  points[1].position = Vec3(3, 4, 0);   // 5 from 0
  points[2].position = Vec3(3, 4, 12);  // 12 from 1, 13 from 0
  points[3].position = Vec3(-1, 0, 0);  // 1 from 0
  const InterestPointSet set(points);
  EXPECT_DOUBLE_EQ(set.nearestNeighbourDistance(0), 1.0);
  EXPECT_DOUBLE_EQ(set.nearestNeighbourDistance(1), 5.0);
  EXPECT_DOUBLE_EQ(set.nearestNeighbourDistance(2), 12.0);
  EXPECT_DOUBLE_EQ(set.nearestNeighbourDistance(3), 1.0);

  const InterestPointSet single(std::vector<InterestPoint>(1));
  EXPECT_TRUE(std::isinf(single.nearestNeighbourDistance(0)));

  std::vector<InterestPoint> twins(2);  // duplicates are 0 apart
  EXPECT_EQ(InterestPointSet(twins).nearestNeighbourDistance(1), 0.0);
}

TEST(InterestPointSet, CopiesAndMovesKeepWorkingTrees) {
  Rng rng(7);
  const auto points = randomPoints(rng, 200, 5.0);
  InterestPointSet original(points);
  const auto expected = bruteForce(points, Vec3(1, 1, 1), 2.5);
  InterestPointSet copy(original);
  InterestPointSet moved(std::move(original));
  EXPECT_EQ(copy.withinRadius(Vec3(1, 1, 1), 2.5), expected);
  EXPECT_EQ(moved.withinRadius(Vec3(1, 1, 1), 2.5), expected);
  InterestPointSet assigned;
  assigned = copy;
  copy = InterestPointSet();  // the assigned set must not share the old tree
  EXPECT_EQ(assigned.withinRadius(Vec3(1, 1, 1), 2.5), expected);
}

TEST(InterestPointSet, ValidateNamesTheBadPoint) {
  std::vector<InterestPoint> points(3);
  EXPECT_NO_THROW(validateInterestPoints(points, "p.pcd"));
  points[2].normal = Vec3(0, 0, 0.9);
  try {
    validateInterestPoints(points, "p.pcd");
    FAIL() << "accepted a normal of length 0.9";
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find("p.pcd"), std::string::npos);
    EXPECT_NE(std::string(error.what()).find("interest point 2"), std::string::npos);
  }
  points[2].normal = Vec3::UnitX();
  points[1].position.y() = std::numeric_limits<double>::infinity();
  EXPECT_THROW(validateInterestPoints(points, "p.pcd"), InputError);
}

}  // namespace
}  // namespace coinspect::world
