#include "coinspect/strategies/star/star_explore.h"

#include <gtest/gtest.h>

#include <cmath>

namespace coinspect::strategies::star {
namespace {

using mapping::CellState;
using mapping::Index3;
using mapping::VoxelGrid;

// 40 x 40 x 20 m of free space at 1 m with a wall across x in [17, 18).
VoxelGrid walledGrid() {
  VoxelGrid grid(Vec3::Zero(), 1.0, Index3(40, 40, 20), CellState::Free);
  for (int z = 0; z < 20; ++z)
    for (int y = 0; y < 40; ++y)
      grid.set(Index3(17, y, z), CellState::Occupied);
  grid.computeClearance(6.0, true);
  return grid;
}

mapping::FrontierCluster clusterAt(const Vec3& corner) {
  mapping::FrontierCluster cluster;
  for (int dy = 0; dy < 2; ++dy)
    for (int dz = 0; dz < 2; ++dz)
      cluster.cells.push_back(corner + Vec3(0.5, 0.5 + dy, 0.5 + dz));
  for (const auto& cell : cluster.cells)
    cluster.centroid += cell / static_cast<double>(cluster.cells.size());
  return cluster;
}

TEST(StarExplore, RingCandidatesCircleTheCentre) {
  RingOptions options;
  options.radii = {4.0};
  options.heights = {0.0, 2.0};
  options.perRing = 4;
  options.minZ = 11.0;  // drops the ring at the centre's height
  const auto candidates = ringCandidates(Vec3(10, 10, 10), options);
  ASSERT_EQ(candidates.size(), 4u);
  for (const auto& c : candidates) {
    EXPECT_NEAR(std::hypot(c.x() - 10.0, c.y() - 10.0), 4.0, 1e-9);
    EXPECT_NEAR(c.z(), 12.0, 1e-9);
  }
  EXPECT_NEAR(candidates[0].x(), 14.0, 1e-9);  // the first angle is +x
}

TEST(StarExplore, BestRingViewpointSeesTheFrontierFromTheOpenSide) {
  const auto grid = walledGrid();
  // Frontier cells 3 m in front of the wall: candidates behind it (x < 17) see nothing.
  const auto cluster = clusterAt(Vec3(20, 20, 10));
  EXPECT_EQ(visibleCells(grid, Vec3(10.5, 20.5, 10.5), cluster.cells, 25.0), 0u);
  EXPECT_EQ(visibleCells(grid, Vec3(25.5, 20.5, 10.5), cluster.cells, 25.0), 4u);
  EXPECT_EQ(visibleCells(grid, Vec3(25.5, 20.5, 10.5), cluster.cells, 2.0), 0u);  // out of range

  RingOptions options;
  options.clearance = 1.5;
  const auto best = bestRingViewpoint(cluster, grid, options);
  ASSERT_TRUE(best.has_value());
  EXPECT_EQ(best->seen, cluster.cells.size());
  EXPECT_GT(best->pose.position.x(), 18.0 + options.clearance - 1e-9);
  EXPECT_EQ(visibleCells(grid, best->pose.position, cluster.cells, options.range),
            cluster.cells.size());
  // It faces the cluster.
  const Vec3 d = cluster.centroid - best->pose.position;
  EXPECT_NEAR(yawChange(best->pose.yaw, std::atan2(d.y(), d.x())), 0.0, 1e-9);

  // No candidate has 20 m of clearance: no viewpoint.
  options.clearance = 20.0;
  EXPECT_FALSE(bestRingViewpoint(cluster, grid, options).has_value());
}

TEST(StarExplore, AtspStartsAtTheRobotAndFollowsTheLine) {
  const std::vector<Pose> poses{
      {Vec3(30, 0, 5), 0.0}, {Vec3(10, 0, 5), 0.0}, {Vec3(20, 0, 5), 0.0}};
  EXPECT_EQ(atspOrder(Pose{Vec3(0, 0, 5), 0.0}, poses, 2.0), (std::vector<size_t>{1, 2, 0}));
  // From the other end (all viewpoints face +x, so only without a yaw cost is this the best).
  EXPECT_EQ(atspOrder(Pose{Vec3(40, 0, 5), M_PI}, poses, 0.0), (std::vector<size_t>{0, 2, 1}));
  EXPECT_TRUE(atspOrder(Pose{}, {}, 1.0).empty());
}

TEST(StarExplore, HeadingChangeWeighsInTheOrder) {
  // Two viewpoints 5 m to either side of the robot, each facing away from it: the way is as
  // long in both orders, but the robot facing one of them turns less by going there first.
  const std::vector<Pose> poses{{Vec3(0, -5, 0), -M_PI / 2}, {Vec3(0, 5, 0), M_PI / 2}};
  EXPECT_EQ(atspOrder(Pose{Vec3::Zero(), M_PI / 2}, poses, 5.0).front(), 1u);
  EXPECT_EQ(atspOrder(Pose{Vec3::Zero(), -M_PI / 2}, poses, 5.0).front(), 0u);
  EXPECT_NEAR(yawChange(3.1, -3.1), 2.0 * M_PI - 6.2, 1e-12);
  EXPECT_NEAR(yawChange(0.0, M_PI), M_PI, 1e-12);
}

}  // namespace
}  // namespace coinspect::strategies::star
