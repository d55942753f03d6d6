#include "coinspect/strategies/star/star_inspect.h"

#include <gtest/gtest.h>

#include <set>

#include "test_boxes.h"

namespace coinspect::strategies::star {
namespace {

using test::makeBox;

using mapping::CellState;
using mapping::Index3;
using mapping::VoxelGrid;

TEST(StarInspect, KeysRoundTripSortedAndUnique) {
  const std::vector<uint64_t> keys{(uint64_t{1} << 63) + 5, 42, 0, 42, 127, 128, ~uint64_t{0}};
  const auto bytes = encodeKeys(keys);
  std::vector<uint64_t> decoded;
  ASSERT_TRUE(decodeKeys(bytes, &decoded));
  const std::set<uint64_t> expected(keys.begin(), keys.end());
  EXPECT_EQ(decoded, std::vector<uint64_t>(expected.begin(), expected.end()));
  // Differences make close keys cheap: 1000 consecutive keys take one byte each.
  std::vector<uint64_t> run;
  for (uint64_t k = 0; k < 1000; ++k)
    run.push_back((uint64_t{7} << 40) + k);
  EXPECT_LT(encodeKeys(run).size(), 1000u + 10u);

  std::vector<uint64_t> untouched{9};
  EXPECT_FALSE(decodeKeys({0x80}, &untouched));  // truncated varint
  EXPECT_EQ(untouched, std::vector<uint64_t>{9});
  ASSERT_TRUE(decodeKeys({}, &untouched));
  EXPECT_TRUE(untouched.empty());
}

TEST(StarInspect, ReceivedPatchesAreDropped) {
  std::vector<planning::InspectionPatch> patches(4);
  for (size_t i = 0; i < patches.size(); ++i)
    patches[i].key = 10 + i;
  std::vector<uint64_t> received;
  ASSERT_TRUE(decodeKeys(encodeKeys({13, 11, 99}), &received));
  const std::set<uint64_t> inspected(received.begin(), received.end());
  const auto open = dropInspected(patches, inspected);
  ASSERT_EQ(open.size(), 2u);
  EXPECT_EQ(open[0].key, 10u);
  EXPECT_EQ(open[1].key, 12u);
}

TEST(StarInspect, SurfaceSplitIsDeterministicAndCompact) {
  // Two equal towers far apart, two photographers: one tower each.
  const std::vector<agent::BoxView> boxes{makeBox({0, 0, 10}, {8, 8, 20}),
                                          makeBox({100, 0, 10}, {8, 8, 20})};
  const SurfaceSplit a(boxes, 0.0, 2), b(boxes, 0.0, 2);
  const uint32_t left = a.ownerOf(Vec3(-4, 0, 10));
  const uint32_t right = a.ownerOf(Vec3(104, 0, 10));
  EXPECT_NE(left, right);
  for (const auto& p : {Vec3(0, 4, 3), Vec3(0, -4, 18), Vec3(4, 0, 20)})
    EXPECT_EQ(a.ownerOf(p), left);
  for (const auto& p : {Vec3(96, 0, 5), Vec3(100, 4, 19)})
    EXPECT_EQ(a.ownerOf(p), right);
  // Every unit computes the same split.
  for (double x = -10; x <= 110; x += 7)
    EXPECT_EQ(a.ownerOf(Vec3(x, 1, 7)), b.ownerOf(Vec3(x, 1, 7)));
  // The standoff point of a share is off its own tower, at the standoff.
  const auto staging = a.standoffPoint(right, Vec3(0, 0, 0), 5.0);
  ASSERT_TRUE(staging.has_value());
  EXPECT_EQ(a.ownerOf(*staging), right);
  EXPECT_GT(staging->x(), 50.0);
  EXPECT_FALSE(a.standoffPoint(7, Vec3::Zero(), 5.0).has_value());
  // One part: everything is its.
  const SurfaceSplit one(boxes, 0.0, 1);
  EXPECT_EQ(one.ownerOf(Vec3(104, 0, 10)), 0u);
}

TEST(StarInspect, ViewsClusterByProximityAndSight) {
  VoxelGrid grid(Vec3::Zero(), 1.0, Index3(30, 30, 10), CellState::Free);
  for (int z = 0; z < 10; ++z)
    for (int y = 0; y < 30; ++y)
      grid.set(Index3(15, y, z), CellState::Occupied);  // a wall at x in [15, 16)
  const std::vector<Vec3> cameras{Vec3(12.5, 5.5, 5.5), Vec3(13.5, 7.5, 5.5),
                                  Vec3(17.5, 5.5, 5.5),   // close to the first, behind the wall
                                  Vec3(12.5, 25.5, 5.5),  // far away
                                  Vec3(11.5, 4.5, 5.5)};
  const auto clusters = clusterViews(cameras, 6.0, &grid);
  ASSERT_EQ(clusters.size(), 3u);
  EXPECT_EQ(clusters[0], (std::vector<size_t>{0, 1, 4}));
  EXPECT_EQ(clusters[1], (std::vector<size_t>{2}));
  EXPECT_EQ(clusters[2], (std::vector<size_t>{3}));
  // Without a grid only the distance counts.
  EXPECT_EQ(clusterViews(cameras, 6.0, nullptr).size(), 2u);
}

}  // namespace
}  // namespace coinspect::strategies::star
