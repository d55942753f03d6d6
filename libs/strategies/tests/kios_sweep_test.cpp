#include <gtest/gtest.h>

#include <cmath>

#include "coinspect/strategies/kios/sweep.h"

namespace coinspect::strategies::kios {
namespace {

Aabb makeVolume(const Vec3& min, const Vec3& max) {
  Aabb volume;
  volume.min = min;
  volume.max = max;
  return volume;
}

TEST(KiosSweep, LongAxisIsTheLongerHorizontalSide) {
  EXPECT_EQ(longHorizontalAxis(makeVolume({0, 0, 0}, {100, 40, 200})), 0);
  EXPECT_EQ(longHorizontalAxis(makeVolume({0, 0, 0}, {30, 80, 10})), 1);
}

TEST(KiosSweep, SlabsCutTheLongAxisIntoEqualContiguousParts) {
  const Aabb volume = makeVolume({-10, 5, 0}, {20, 95, 30});  // long axis: y
  const auto slabs = splitSlabs(volume, 3);
  ASSERT_EQ(slabs.size(), 3u);
  EXPECT_DOUBLE_EQ(slabs.front().min.y(), 5.0);
  EXPECT_DOUBLE_EQ(slabs.back().max.y(), 95.0);
  for (size_t k = 0; k < slabs.size(); ++k) {
    EXPECT_NEAR(slabs[k].size().y(), 30.0, 1e-9);
    EXPECT_DOUBLE_EQ(slabs[k].min.x(), -10.0);  // full width and height
    EXPECT_DOUBLE_EQ(slabs[k].max.x(), 20.0);
    EXPECT_DOUBLE_EQ(slabs[k].max.z(), 30.0);
    if (k > 0) {
      EXPECT_DOUBLE_EQ(slabs[k].min.y(), slabs[k - 1].max.y());
    }
  }
  EXPECT_EQ(splitSlabs(volume, 0).size(), 1u);
}

TEST(KiosSweep, PassesRunAlongTheLongAxisOutsideTheVolumeThenAboveIt) {
  const Aabb volume = makeVolume({0, 0, 0}, {100, 30, 40});  // long axis: x, 30 m wide
  const Aabb slab = splitSlabs(volume, 2)[1];                // x in [50, 100]
  SweepOptions options;
  options.standoff = 8.0;
  options.laneSpacing = 20.0;  // two passes above the 30 m width
  options.spacing = 5.0;
  options.heights = {10.0, 25.0};
  const Vec3 near(120, 50, 0);  // beyond the high end, on the high side
  const auto route = lawnmowerSweep(volume, slab, options, near);
  ASSERT_FALSE(route.empty());
  EXPECT_NEAR(route.front().x(), 100.0, 1e-9);
  EXPECT_NEAR(route.front().y(), 38.0, 1e-9);
  int sides = 0, above = 0;
  bool sawHeight[2] = {false, false};
  for (const auto& p : route) {
    EXPECT_GE(p.x(), 50.0 - 1e-9);
    EXPECT_LE(p.x(), 100.0 + 1e-9);
    if (p.z() > volume.max.z()) {
      ++above;
      EXPECT_GT(p.y(), 0.0);
      EXPECT_LT(p.y(), 30.0);
    } else {
      ++sides;
      EXPECT_TRUE(std::abs(p.y() + 8.0) < 1e-9 || std::abs(p.y() - 38.0) < 1e-9) << p.y();
      sawHeight[0] |= p.z() == 10.0;
      sawHeight[1] |= p.z() == 25.0;
    }
  }
  EXPECT_TRUE(sawHeight[0] && sawHeight[1]);
  EXPECT_EQ(sides, 4 * 11);  // 2 heights x 2 sides x (50 m / 5 m + 1) points
  EXPECT_EQ(above, 2 * 11);
  // Consecutive points of a pass are at most `spacing` apart along the long axis.
  for (size_t i = 1; i < route.size(); ++i)
    if (route[i].y() == route[i - 1].y() && route[i].z() == route[i - 1].z()) {
      EXPECT_LE(std::abs(route[i].x() - route[i - 1].x()), 5.0 + 1e-9);
    }
}

}  // namespace
}  // namespace coinspect::strategies::kios
