#include "coinspect/strategies/runtime/scan_cells_cache.h"

#include <gtest/gtest.h>

namespace coinspect::strategies::runtime {
namespace {

agent::KeyFrameView wallFrame(double x) {
  auto frame = std::make_shared<agent::KeyFrame>();
  frame->position = agent::Vec3(0.1, 0.2, 1.3);
  for (double y = -2.0; y <= 2.0; y += 0.1)
    for (double z = 0.0; z <= 3.0; z += 0.1)
      frame->points.emplace_back(static_cast<float>(x), static_cast<float>(y),
                                 static_cast<float>(z));
  return frame;
}

// Robots inserting one frame object share its cells; a map of another resolution or range cap
// gets its own, and the least recently used frame leaves a full cache first.
TEST(ScanCellsCache, MapsOfTheSameOptionsShareAFramesCellsUntilItLeavesTheCache) {
  ScanCellsCache cache(8);
  const mapping::OccupancyMap map1({0.5, 30.0}), map2({0.5, 30.0, false});
  const mapping::OccupancyMap coarse({1.0, 30.0}), shortSighted({0.5, 5.0});
  const auto a = wallFrame(6.25), b = wallFrame(8.25), c = wallFrame(10.25);
  const auto cellsA = cache.cellsOf(a, map1);
  EXPECT_EQ(cache.cellsOf(a, map2), cellsA);  // the clearing rule is the receiver's own
  EXPECT_EQ(cellsA->codes, map1.scanCells(a->position, a->points).codes);
  EXPECT_NE(cache.cellsOf(a, coarse), cellsA);
  EXPECT_NE(cache.cellsOf(a, shortSighted), cellsA);
  EXPECT_EQ(cache.cellsOf(a, coarse)->resolution, 1.0);
  // An equal frame that is another object is found again (the relay interns equal frames).
  const auto copy = std::make_shared<const agent::KeyFrame>(*a);
  EXPECT_NE(cache.cellsOf(copy, map1), cellsA);
  EXPECT_EQ(cache.cellsOf(copy, map1)->codes, cellsA->codes);

  ScanCellsCache small(2);
  const auto smallA = small.cellsOf(a, map1), smallB = small.cellsOf(b, map1);
  EXPECT_EQ(small.cellsOf(a, map1), smallA);  // a is the most recent now
  small.cellsOf(c, map1);                     // b leaves
  EXPECT_EQ(small.cellsOf(a, map1), smallA);
  EXPECT_NE(small.cellsOf(b, map1), smallB);
}

}  // namespace
}  // namespace coinspect::strategies::runtime
