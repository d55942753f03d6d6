#include "coinspect/strategies/runtime/robot_map.h"

#include <gtest/gtest.h>

#include "test_boxes.h"

namespace coinspect::strategies::runtime {
namespace {

using test::makeBox;

// One scan from (0, 0, 5): a wall at x = 10 inside the box, a wall at y = 8 along the box, 3 m
// outside it, and the ground in front of the first wall.
agent::KeyFrame wallsAndGround() {
  agent::KeyFrame frame;
  frame.producer = "jurong";
  frame.position = Vec3(0, 0, 5);
  for (float a = -4.0f; a <= 4.0f; a += 0.25f)
    for (float z = 1.0f; z <= 9.0f; z += 0.25f) {
      frame.points.emplace_back(10.2f, a, z);         // the box's wall
      frame.points.emplace_back(12.0f + a, 8.2f, z);  // a wall 3 m from the box
    }
  for (float x = 2.0f; x <= 9.0f; x += 0.25f)
    for (float y = -4.0f; y <= 4.0f; y += 0.25f)
      frame.points.emplace_back(x, y, 0.0f);
  return frame;
}

TEST(RobotMap, TheRegionAlsoHoldsTheIncludedPoints) {
  const std::vector<BoxView> boxes = {makeBox(Vec3(12, 0, 5), Vec3(6, 10, 10))};
  RobotMapOptions options;
  options.regionMargin = 5.0;
  const RobotMap plain(options, boxes, 0.0);
  EXPECT_DOUBLE_EQ(plain.region().min.y(), -10.0);  // box from y = -5, 5 m of margin
  options.include = {Vec3(12, -30, 0.1)};
  const RobotMap grown(options, boxes, 0.0);
  EXPECT_DOUBLE_EQ(grown.region().min.y(), -32.0);  // 2 m of room around the point
  EXPECT_EQ(grown.region().max, plain.region().max);
  EXPECT_TRUE(grown.grid().contains(grown.grid().cellOf(Vec3(12, -30, 0.1))));
}

// A blob the size of a UAV seen at (5, 0, 3), in the open, and one at (8.5, 0, 3), within the
// 2 m margin of the box (x from 9): rays passing later clear the first one only, and only with
// raysClearAwayFromBoxes; the box's wall behind them stays.
TEST(RobotMap, RaysClearWhatWasSeenInTheOpenButNotNearTheBoxes) {
  const std::vector<BoxView> boxes = {makeBox(Vec3(12, 0, 5), Vec3(6, 10, 10))};
  agent::KeyFrame blobs;
  blobs.position = Vec3(0, 0, 3);
  for (const float x : {5.1f, 8.6f})
    blobs.points.emplace_back(x, 0.1f, 3.1f);
  agent::KeyFrame wall = wallsAndGround();
  wall.position = Vec3(0, 0, 3);
  for (const bool clears : {false, true}) {
    RobotMapOptions options;
    options.mapResolution = 0.5;
    options.boxMargin = 2.0;
    options.raysClearAwayFromBoxes = clears;
    RobotMap map(options, boxes, 0.0);
    map.insertFrame(std::make_shared<const agent::KeyFrame>(blobs));
    ASSERT_EQ(map.map().state(Vec3(5.25, 0.25, 3.25)), mapping::CellState::Occupied);
    for (int i = 0; i < 12; ++i)
      map.insertFrame(std::make_shared<const agent::KeyFrame>(wall));
    EXPECT_EQ(map.map().state(Vec3(5.25, 0.25, 3.25)),
              clears ? mapping::CellState::Free : mapping::CellState::Occupied)
        << clears;
    EXPECT_EQ(map.map().state(Vec3(8.75, 0.25, 3.25)), mapping::CellState::Occupied) << clears;
    EXPECT_EQ(map.map().state(Vec3(10.25, 0.25, 3.25)), mapping::CellState::Occupied) << clears;
  }
}

TEST(RobotMap, SurfaceNearBoxesKeepsMappedStructureInABoxNotTheGroundNorStructureFarFromBoxes) {
  const std::vector<BoxView> boxes = {makeBox(Vec3(12, 0, 5), Vec3(6, 10, 10))};
  RobotMapOptions options;
  options.mapResolution = 0.5;
  RobotMap map(options, boxes, 0.0);
  map.insertFrame(std::make_shared<const agent::KeyFrame>(wallsAndGround()));
  const auto all = map.map().surfaceVoxels(map.region().min, map.region().max);
  const auto near = map.surfaceNearBoxes(boxes, 1.0);
  ASSERT_FALSE(near.empty());
  EXPECT_LT(near.size(), all.size());
  size_t wall = 0;
  for (const auto& voxel : near) {
    EXPECT_GT(voxel.centre.z(), 0.5) << "ground voxel kept at " << voxel.centre.transpose();
    EXPECT_LT(voxel.centre.y(), 7.0) << "far wall kept at " << voxel.centre.transpose();
    if (std::abs(voxel.centre.x() - 10.25) < 0.3) ++wall;
  }
  EXPECT_GT(wall, 100u);  // 8 x 8 m of wall in 0.5 m cells
  // With a wider reach the far wall counts too.
  EXPECT_GT(map.surfaceNearBoxes(boxes, 5.0).size(), near.size());
}

// A rebuild reads again only the cells where the map changed and transforms the clearance
// only around the cells whose blocking changed; after every rebuild the grid must equal one read
// whole from the map (unknown cells as the blocking zone left them) with the whole transform.
TEST(RobotMap, GridRebuiltWhereTheMapChangedEqualsAGridReadWhole) {
  const std::vector<BoxView> boxes = {makeBox(Vec3(12, 0, 5), Vec3(6, 10, 10))};
  for (const double gridResolution : {0.5, 1.0}) {
    RobotMapOptions options;
    options.mapResolution = 0.5;
    options.gridResolution = gridResolution;
    RobotMap map(options, boxes, 0.0);
    const mapping::VoxelGrid zone = map.grid();  // no scan yet: unknown where it stays blocked
    const auto check = [&](int step) {
      const mapping::VoxelGrid& grid = map.grid();
      const mapping::VoxelGrid read = map.map().toVoxelGrid(
          grid.origin(), grid.origin() + grid.size().cast<double>() * grid.resolution(),
          grid.resolution());
      EXPECT_EQ(read.size(), grid.size());
      mapping::VoxelGrid expected = read;
      for (int z = 0; z < grid.size().z(); ++z)
        for (int y = 0; y < grid.size().y(); ++y)
          for (int x = 0; x < grid.size().x(); ++x) {
            const mapping::Index3 cell(x, y, z);
            if (read.state(cell) == mapping::CellState::Unknown)
              expected.set(cell, zone.state(cell));
          }
      expected.computeClearance(options.clearanceCap, true);
      size_t changed = 0, wrong = 0;
      for (int z = 0; z < grid.size().z(); ++z)
        for (int y = 0; y < grid.size().y(); ++y)
          for (int x = 0; x < grid.size().x(); ++x) {
            const mapping::Index3 cell(x, y, z);
            const bool same = grid.state(cell) == expected.state(cell) &&
                              grid.clearance(cell) == expected.clearance(cell);
            if (!same && wrong++ == 0)
              ADD_FAILURE() << gridResolution << " step " << step << " cell " << cell.transpose();
            changed += grid.state(cell) != zone.state(cell);
          }
      EXPECT_EQ(wrong, 0U) << gridResolution << " step " << step;
      return changed;
    };
    // The same walls and ground seen from three places, then nothing new.
    size_t changedBefore = 0;
    const Vec3 offsets[] = {Vec3(0, 0, 0), Vec3(-2, 3, 2), Vec3(1, -4, -1), Vec3(1, -4, -1)};
    for (int step = 0; step < 4; ++step) {
      agent::KeyFrame frame = wallsAndGround();
      frame.position += offsets[step];
      if (step > 0)
        for (auto& p : frame.points)
          p += Eigen::Vector3f(0.0f, 0.5f * static_cast<float>(step), 0.0f);
      map.insertFrame(std::make_shared<const agent::KeyFrame>(frame));
      ASSERT_TRUE(map.refresh(10.0 * (step + 1), true));
      const size_t changed = check(step);
      EXPECT_GE(changed, changedBefore);
      if (step < 3) {
        EXPECT_GT(changed, changedBefore) << "step " << step << " changed nothing";
      }
      changedBefore = changed;
    }
  }
}

}  // namespace
}  // namespace coinspect::strategies::runtime
