#include "coinspect/strategies/coinspect/work_partition.h"

#include <gtest/gtest.h>

#include "test_boxes.h"

namespace coinspect::strategies::coinspect_strategy {
namespace {

using test::makeBox;

TEST(WorkPartition, FaceSamplesCoverTheAreaAndSkipTheFloor) {
  const std::vector<agent::BoxView> boxes = {makeBox(Vec3(0, 0, 5), Vec3(10, 4, 10))};
  const auto items = sampleBoxFaces(boxes, 2.0, 0.0, 1.0);
  double area = 0.0;
  for (const auto& item : items) {
    area += item.weight;
    EXPECT_GT(item.normal.z(), -0.7) << "the bottom face touches the ground";
  }
  EXPECT_NEAR(area, 2 * (10 * 10 + 4 * 10) + 10 * 4, 1e-9);
  // A raised box keeps its bottom face.
  const auto raised = sampleBoxFaces({makeBox(Vec3(0, 0, 20), Vec3(10, 4, 10))}, 2.0, 0.0, 1.0);
  EXPECT_GT(raised.size(), items.size());
}

TEST(WorkPartition, RegionsFollowCapacitiesAndAreCompact) {
  const std::vector<agent::BoxView> boxes = {makeBox(Vec3(0, 0, 25), Vec3(20, 10, 50)),
                                             makeBox(Vec3(60, 0, 25), Vec3(20, 10, 50))};
  const auto items = sampleBoxFaces(boxes, 2.0, 0.0, 1.0);
  const std::vector<double> capacities = {0.5, 1.0, 1.0, 1.0, 0.5};
  const auto region = partitionWork(items, capacities);
  std::vector<double> weight(capacities.size(), 0.0);
  double total = 0.0;
  for (size_t i = 0; i < items.size(); ++i) {
    weight[region[i]] += items[i].weight;
    total += items[i].weight;
  }
  for (size_t r = 0; r < capacities.size(); ++r)
    EXPECT_NEAR(weight[r] / total, capacities[r] / 4.0, 0.03) << "region " << r;
  // With four equal shares the first split falls between the two towers 60 m apart: no
  // region spans both.
  const auto equal = partitionWork(items, {1.0, 1.0, 1.0, 1.0});
  for (uint32_t r = 0; r < 4; ++r) {
    bool west = false, east = false;
    for (size_t i = 0; i < items.size(); ++i)
      if (equal[i] == r) (items[i].position.x() < 30 ? west : east) = true;
    EXPECT_FALSE(west && east) << "region " << r;
  }
  EXPECT_EQ(partitionWork(items, capacities), region);  // deterministic
}

}  // namespace
}  // namespace coinspect::strategies::coinspect_strategy
