#include <gtest/gtest.h>

#include <algorithm>
#include <set>

#include "coinspect/strategies/kios/waypoints.h"

namespace coinspect::strategies::kios {
namespace {

using mapping::CellState;
using mapping::Index3;
using mapping::VoxelGrid;

// 30 m cube of free cells with a wall of occupied cells at x in [15, 16), y and z in [8, 22).
VoxelGrid wallGrid() {
  VoxelGrid grid(Vec3::Zero(), 1.0, Index3(30, 30, 30), CellState::Free);
  for (int z = 8; z < 22; ++z)
    for (int y = 8; y < 22; ++y)
      grid.set(Index3(15, y, z), CellState::Occupied);
  grid.computeClearance(6.0, false);
  return grid;
}

BoxView wallBox() {
  BoxView box;
  box.center = Vec3(15.5, 15, 15);
  box.size = Vec3(1, 14, 14);
  return box;
}

TEST(KiosWaypoints, ViewCellsAreFreeCellsBesideOccupiedOnesLookingAtThem) {
  const VoxelGrid grid = wallGrid();
  const auto cells = viewCells(grid, {wallBox()}, 1.0);
  ASSERT_FALSE(cells.empty());
  size_t front = 0;
  for (const auto& cell : cells) {
    // The sample sits on the face between a free cell and an occupied one; the view direction
    // (-normal) leads into the occupied cell, the normal back into the free one.
    EXPECT_EQ(grid.state(grid.cellOf(cell.centre - 0.25 * cell.normal)), CellState::Occupied);
    EXPECT_EQ(grid.state(grid.cellOf(cell.centre + 0.25 * cell.normal)), CellState::Free);
    if (std::abs(cell.normal.x()) > 0.99) {
      ++front;
      EXPECT_TRUE(std::abs(cell.centre.x() - 15.0) < 1e-9 ||
                  std::abs(cell.centre.x() - 16.0) < 1e-9);
    }
  }
  EXPECT_EQ(front, 2u * 14u * 14u);  // both big faces of the wall, one sample per cell
  // Far from every box nothing counts.
  BoxView far = wallBox();
  far.center = Vec3(100, 100, 100);
  EXPECT_TRUE(viewCells(grid, {far}, 1.0).empty());
}

TEST(KiosWaypoints, TheGroundInsideABoxIsNotASurfaceToInspect) {
  // The wall stands on the ground (the cells of z in [0, 1)); its box reaches down to it.
  VoxelGrid grid = wallGrid();
  for (int y = 0; y < 30; ++y)
    for (int x = 0; x < 30; ++x)
      grid.set(Index3(x, y, 0), CellState::Occupied);
  for (int z = 1; z < 8; ++z)
    for (int y = 8; y < 22; ++y)
      grid.set(Index3(15, y, z), CellState::Occupied);
  BoxView box = wallBox();
  box.center.z() = 11.0;
  box.size.z() = 22.0;
  // The cells in the corner between the wall's foot and the ground look at both (45 degrees):
  // they stay.
  const auto countUp = [](const std::vector<mapping::SurfaceVoxel>& cells) {
    return std::count_if(cells.begin(), cells.end(),
                         [](const mapping::SurfaceVoxel& c) { return c.normal.z() > 0.99; });
  };
  const auto all = viewCells(grid, {box}, 1.0);
  const auto above = viewCells(grid, {box}, 1.0, 0.0);
  EXPECT_GT(countUp(all), 2);     // the ground beside the wall, inside the box's margin
  EXPECT_EQ(countUp(above), 14);  // the wall's top only, one sample per cell
  EXPECT_EQ(all.size() - above.size(), static_cast<size_t>(countUp(all) - 14));
}

TEST(KiosWaypoints, WaypointsHoldTheCameraAtTheDistanceFacingTheWall) {
  const VoxelGrid grid = wallGrid();
  WaypointOptions options;
  options.spacing = 4.0;
  options.viewpoint.distance = 5.0;
  options.viewpoint.cameraOffset = Vec3::Zero();
  planning::PathSearchOptions path;
  path.clearance = 1.5;
  const auto waypoints = inspectionWaypoints(grid, {wallBox()}, options, path);
  ASSERT_GT(waypoints.size(), 10u);
  size_t frontal = 0;
  std::set<uint64_t> ids;
  for (const auto& w : waypoints) {
    ids.insert(w.id);
    EXPECT_GE(grid.clearance(grid.cellOf(w.body)), 1.5);
    // The view direction leads from the body into the wall.
    EXPECT_EQ(grid.state(grid.cellOf(w.target + 0.25 * w.view)), CellState::Occupied);
    EXPECT_GT(w.view.dot(w.target - w.body), 0.0);
    if (std::abs(w.view.x()) > 0.99) {
      ++frontal;
      EXPECT_NEAR((w.target - w.body).norm(), 5.0, 1e-6);
      EXPECT_NEAR(std::abs(w.body.x() - 15.5), 5.5, 1e-6);  // 5 m from either face
      EXPECT_NEAR(std::cos(w.yaw), w.view.x(), 1e-6);       // the body faces the wall
    }
  }
  EXPECT_GE(frontal, 2u * 4u);  // both faces, several bins each
  EXPECT_EQ(ids.size(), waypoints.size());
  EXPECT_TRUE(std::is_sorted(waypoints.begin(), waypoints.end(),
                             [](const auto& a, const auto& b) { return a.id < b.id; }));
}

InspectionWaypoint at(uint64_t id, const Vec3& body) {
  InspectionWaypoint w;
  w.id = id;
  w.body = body;
  return w;
}

TEST(KiosWaypoints, TwoRobotsWithTheSameKnowledgeGetTheSameAssignment) {
  std::vector<InspectionWaypoint> waypoints;
  uint64_t id = 1000;
  for (int i = 0; i < 12; ++i) {
    waypoints.push_back(at(id += 7, Vec3(2.0 * i, 3.0, 5.0)));
    waypoints.push_back(at(id += 13, Vec3(40.0 + 1.5 * i, -4.0 + 0.5 * i, 6.0)));
  }
  const std::vector<Vec3> vehicles = {Vec3(0, 0, 5), Vec3(60, 0, 5)};
  // The second robot received the same waypoints in another order.
  std::vector<InspectionWaypoint> shuffled = waypoints;
  std::reverse(shuffled.begin(), shuffled.end());
  std::rotate(shuffled.begin(), shuffled.begin() + 5, shuffled.end());
  const auto a = assignWaypoints(vehicles, waypoints, {});
  const auto b = assignWaypoints(vehicles, shuffled, {});
  ASSERT_EQ(a.size(), 2u);
  ASSERT_EQ(b.size(), 2u);
  std::multiset<uint64_t> assigned;
  for (size_t v = 0; v < 2; ++v) {
    ASSERT_EQ(a[v].size(), b[v].size());
    for (size_t k = 0; k < a[v].size(); ++k) {
      EXPECT_EQ(waypoints[a[v][k]].id, shuffled[b[v][k]].id);
      assigned.insert(waypoints[a[v][k]].id);
    }
  }
  EXPECT_EQ(assigned.size(), waypoints.size());
  EXPECT_EQ(std::set<uint64_t>(assigned.begin(), assigned.end()).size(), waypoints.size());
  // Min-max: each vehicle takes the cluster next to it, neither idles.
  for (const size_t i : a[0])
    EXPECT_LT(waypoints[i].body.x(), 30.0);
  for (const size_t i : a[1])
    EXPECT_GT(waypoints[i].body.x(), 30.0);
  EXPECT_TRUE(assignWaypoints(vehicles, {}, {})[0].empty());
}

}  // namespace
}  // namespace coinspect::strategies::kios
