#include "coinspect/strategies/slei/fleet_plan.h"

#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>

#include "test_boxes.h"

namespace coinspect::strategies::slei {
namespace {

using test::makeBox;

TEST(SleiFleetPlan, EvenSplitGivesTheRemainderToTheFirstSubgroups) {
  EXPECT_EQ(inspectorsPerSubgroup(8, 3, true), (std::vector<size_t>{3, 3, 2}));
  EXPECT_EQ(inspectorsPerSubgroup(4, 2, true), (std::vector<size_t>{2, 2}));
  EXPECT_EQ(inspectorsPerSubgroup(1, 2, true), (std::vector<size_t>{1, 0}));
  EXPECT_TRUE(inspectorsPerSubgroup(3, 0, true).empty());
}

TEST(SleiFleetPlan, VolumeSplitFloorsSharesAndHandsTheRestToTheLargestFractions) {
  // Shares of 5 by 1:2:2 = 1, 2, 2 exactly; by 1:1:3 = 1, 1, 3; by 3:3:4 of 7 = 2.1, 2.1, 2.8.
  EXPECT_EQ(inspectorsPerSubgroup(5, 3, false, {1, 2, 2}), (std::vector<size_t>{1, 2, 2}));
  EXPECT_EQ(inspectorsPerSubgroup(5, 3, false, {1, 1, 3}), (std::vector<size_t>{1, 1, 3}));
  EXPECT_EQ(inspectorsPerSubgroup(7, 3, false, {3, 3, 4}), (std::vector<size_t>{2, 2, 3}));
  // Weights that cannot be used fall back to the even split.
  EXPECT_EQ(inspectorsPerSubgroup(4, 2, false, {0, 0}), (std::vector<size_t>{2, 2}));
}

TEST(SleiFleetPlan, NearestFreeBoxSkipsAssignedOnesAndMeasuresHorizontally) {
  const std::vector<agent::BoxView> boxes{makeBox({10, 0, 50}, {2, 2, 2}),
                                          makeBox({0, 12, 1}, {2, 2, 2}),
                                          makeBox({-20, 0, 1}, {2, 2, 2})};
  EXPECT_EQ(nearestFreeBox(boxes, {0, 0, 0}, agent::Vec3::Zero()), 0);  // height ignored
  EXPECT_EQ(nearestFreeBox(boxes, {1, 0, 0}, agent::Vec3::Zero()), 1);
  EXPECT_EQ(nearestFreeBox(boxes, {1, 1, 1}, agent::Vec3::Zero()), -1);
}

// Urgent areas ([features] priority_boxes) are dealt first, the nearest of them; then the rest.
TEST(SleiFleetPlan, NearestFreeBoxTakesHighPriorityBoxesFirst) {
  std::vector<agent::BoxView> boxes{makeBox({10, 0, 1}, {2, 2, 2}), makeBox({0, 30, 1}, {2, 2, 2}),
                                    makeBox({-20, 0, 1}, {2, 2, 2})};
  boxes[1].highPriority = boxes[2].highPriority = true;
  EXPECT_EQ(nearestFreeBox(boxes, {0, 0, 0}, agent::Vec3::Zero()), 2);
  EXPECT_EQ(nearestFreeBox(boxes, {0, 0, 1}, agent::Vec3::Zero()), 1);
  EXPECT_EQ(nearestFreeBox(boxes, {0, 1, 1}, agent::Vec3::Zero()), 0);
}

// SLEI-PRE: boxes on a line at x = 0, 10, ..., 50; subgroups start at 0 and 50 and take turns,
// each the free box nearest its last: 10 (from 0), 40 (from 50), 20, 30.
TEST(SleiFleetPlan, FixedBoxOrdersDealTheRestInTurnsNearestFirst) {
  std::vector<agent::BoxView> boxes;
  for (int i = 0; i < 6; ++i)
    boxes.push_back(makeBox({10.0 * i, 0, 2}, {2, 2, 4}));
  const auto orders = fixedBoxOrders(boxes, {0, 5});
  ASSERT_EQ(orders.size(), 2u);
  EXPECT_EQ(orders[0], (std::vector<int32_t>{1, 2}));
  EXPECT_EQ(orders[1], (std::vector<int32_t>{4, 3}));
  // A subgroup without a first box gets nothing; the others share every box.
  const auto uneven = fixedBoxOrders(boxes, {-1, 0});
  EXPECT_TRUE(uneven[0].empty());
  EXPECT_EQ(uneven[1], (std::vector<int32_t>{1, 2, 3, 4, 5}));
}

TEST(SleiFleetPlan, CornersLieOutsideTheBoxAndAwayFromIt) {
  const auto box = makeBox({0, 0, 5}, {10, 6, 10});
  const Vec3 corner = boxCorner(box, 2.0, 0.5, {20, 20, 0});
  EXPECT_TRUE(corner.isApprox(Vec3(7, 5, 0.5)));
  const Vec3 away = awayFromBox(box, corner, 5.0, 6.0);
  EXPECT_NEAR(std::hypot(away.x(), away.y()), std::hypot(7.0, 5.0) + 5.0, 1e-9);
  EXPECT_DOUBLE_EQ(away.z(), 6.0);
}

// Any two wait points farther apart than the flight's 4 m hold distance (2.5 m apart on one
// line, a waiting inspector held the next one off its point for a whole run), outside the box.
TEST(SleiFleetPlan, WaitPointsStandFartherApartThanTheHoldDistance) {
  const auto box = makeBox({0, 0, 5}, {10, 6, 10});
  const Vec3 corner = boxCorner(box, 2.0, 0.5, {20, 20, 0});
  std::vector<Vec3> points;
  for (size_t k = 0; k < 10; ++k) {
    points.push_back(waitPointOffCorner({box}, 0, corner, k, 5.0, 6.0));
    EXPECT_DOUBLE_EQ(points.back().z(), 6.0);
    EXPECT_TRUE(points.back().x() > 6.5 || points.back().y() > 4.5) << k;  // 1.5 m off the box
    EXPECT_LT((points.back() - Vec3(corner.x(), corner.y(), 6.0)).norm(), 15.0) << k;
  }
  for (size_t i = 0; i < points.size(); ++i)
    for (size_t j = i + 1; j < points.size(); ++j)
      EXPECT_GE((points[i] - points[j]).norm(), 5.0 - 1e-9) << i << " " << j;
  // The first two either side of the line from the centre through the corner, 3 m out.
  const Vec3 middle = 0.5 * (points[0] + points[1]);
  EXPECT_TRUE(middle.isApprox(awayFromBox(box, corner, 3.0, 6.0), 1e-9));
  // Another box where the first one would be: it is left out, the others move up.
  const Vec3 first = points[0];
  const auto neighbour = makeBox(Vec3(first.x(), first.y(), 5), {2, 2, 10});
  EXPECT_TRUE(waitPointOffCorner({box, neighbour}, 0, corner, 0, 5.0, 6.0).isApprox(points[1]));

  // caric-team's relay: 4 on the first circle of 3 m (as before), then a wider one; no two
  // closer than the hold distance.
  const Vec3 relay(0, 0, 3);
  std::vector<Vec3> around;
  for (size_t i = 0; i < 9; ++i)
    around.push_back(relayWaitPoint(relay, i, 9, 3.0, 4.0, 5.0));
  for (size_t i = 0; i < 4; ++i)
    EXPECT_NEAR((around[i] - relay).norm(), 3.0, 1e-9) << i;
  for (size_t i = 4; i < 9; ++i)
    EXPECT_NEAR((around[i] - relay).norm(), 8.0, 1e-9) << i;
  for (size_t i = 0; i < around.size(); ++i)
    for (size_t j = i + 1; j < around.size(); ++j)
      EXPECT_GT((around[i] - around[j]).norm(), 4.0) << i << " " << j;
  EXPECT_TRUE(relayWaitPoint(relay, 0, 1, 3.0, 4.0, 5.0).isApprox(Vec3(3, 0, 3), 1e-9));
}

TEST(SleiFleetPlan, CornersInsideAnotherBoxAreSkipped) {
  // Four boxes as the quadrants of one building (slei-b): the inner corner of a quadrant, 2 m
  // out in x and y, lies inside the diagonally opposite one.
  std::vector<agent::BoxView> boxes;
  for (const double x : {-4.0, 4.0})
    for (const double y : {-4.0, 4.0})
      boxes.push_back(makeBox({x, y, 5}, {8, 8, 10}));
  const Vec3 from(20, 25, 0);
  EXPECT_TRUE(boxCorner(boxes[0], 2.0, 0.5, from).isApprox(Vec3(2, 2, 0.5)));
  EXPECT_TRUE(boxCorner(boxes, 0, 2.0, 0.5, from).isApprox(Vec3(-10, 2, 0.5)));
  // Nothing in the way: the same corner as for the box alone.
  EXPECT_TRUE(boxCorner(boxes, 1, 2.0, 0.5, from).isApprox(boxCorner(boxes[1], 2.0, 0.5, from)));
  // Every corner inside some box: the nearest.
  const std::vector<agent::BoxView> nested{makeBox({0, 0, 5}, {2, 2, 10}),
                                           makeBox({0, 0, 5}, {40, 40, 10})};
  EXPECT_TRUE(boxCorner(nested, 0, 2.0, 0.5, from).isApprox(boxCorner(nested[0], 2.0, 0.5, from)));
}

// A wall 20 m long across y = 10 from x = -10 to 10, as LiDAR points from 0 to 4 m high; the
// ground at z = 0.
std::vector<Eigen::Vector3f> wallPoints() {
  std::vector<Eigen::Vector3f> points;
  for (float x = -10; x <= 10; x += 0.2f)
    for (float z = 0; z <= 4; z += 0.25f)
      points.emplace_back(x, 10.0f, z);
  return points;
}

TEST(SleiFleetPlan, TheStationLearnsWallsFromLidarPointsAtItsHeightOnly) {
  const std::vector<agent::BoxView> boxes{makeBox({0, -10, 5}, {4, 4, 10})};
  auto ground = stationGroundGrid(boxes, planning::Vec2(0, 20), 0.5);
  EXPECT_TRUE(ground.blocked(planning::Vec2(0, -10)));    // the box's footprint
  EXPECT_TRUE(ground.blocked(planning::Vec2(2.9, -10)));  // + radius + clearance
  EXPECT_FALSE(ground.blocked(planning::Vec2(3.2, -10)));
  EXPECT_FALSE(ground.blocked(planning::Vec2(0, 10)));  // the wall is not known yet
  EXPECT_FALSE(ground.path(planning::Vec2(0, 0), planning::Vec2(0, 20)).empty());
  // The ground and an overhang teach nothing; a wall does, once.
  std::vector<Eigen::Vector3f> ground_and_roof;
  for (float x = -5; x <= 5; x += 0.2f)
    ground_and_roof.emplace_back(x, 5.0f, 0.1f);
  for (float x = -5; x <= 5; x += 0.2f)
    ground_and_roof.emplace_back(x, 5.0f, 3.0f);
  EXPECT_EQ(blockGroundObstacles(ground, ground_and_roof, 0.0, 1.0), 0u);
  EXPECT_GT(blockGroundObstacles(ground, wallPoints(), 0.0, 1.0), 0u);
  EXPECT_EQ(blockGroundObstacles(ground, wallPoints(), 0.0, 1.0), 0u);
  EXPECT_TRUE(ground.blocked(planning::Vec2(0, 10)));
  EXPECT_TRUE(ground.blocked(planning::Vec2(5, 10.8)));  // inflated
  // The way north now goes round the wall's end.
  const auto path = ground.path(planning::Vec2(0, 0), planning::Vec2(0, 20));
  ASSERT_FALSE(path.empty());
  const bool round = std::any_of(path.begin(), path.end(),
                                 [](const planning::Vec2& p) { return std::abs(p.x()) > 10.0; });
  EXPECT_TRUE(round);
}

TEST(SleiFleetPlan, ExplorersTakeTheNearestBoxesInTurnAndMeetTheStationInAChain) {
  std::vector<agent::FleetMember> fleet{
      {"gcs", agent::Role::GroundStation}, {"e1", agent::Role::Explorer},
      {"i1", agent::Role::Photographer},   {"e2", agent::Role::Explorer},
      {"i2", agent::Role::Photographer},   {"i3", agent::Role::Photographer}};
  const std::vector<agent::BoxView> boxes{makeBox({40, 0, 5}, {4, 4, 10}),
                                          makeBox({10, 0, 5}, {4, 4, 10}),
                                          makeBox({20, 0, 5}, {4, 4, 10})};
  PlanOptions options;
  const auto shares = stationShares(fleet, boxes);
  ASSERT_EQ(shares.size(), 1u);  // one station: everything is its
  const auto plan = makeFleetPlan(shares[0], boxes, Vec3(0, 0, 0.1), 0.0, 100.0, options);
  ASSERT_EQ(plan.subgroups.size(), 2u);
  EXPECT_EQ(plan.subgroups[0].station, 0u);
  EXPECT_EQ(plan.subgroups[0].explorer, 1u);
  EXPECT_EQ(plan.subgroups[0].box, 1);  // nearest the station
  EXPECT_EQ(plan.subgroups[1].explorer, 3u);
  EXPECT_EQ(plan.subgroups[1].box, 2);  // nearest the first choice
  EXPECT_EQ(plan.subgroups[0].inspectors, (std::vector<uint32_t>{2, 4}));
  EXPECT_EQ(plan.subgroups[1].inspectors, (std::vector<uint32_t>{5}));
  // First meetings: the corner of each box nearest the previous stop, 60 s + 20 s per leg after
  // now, legs driven at 1 m/s. Box 1 spans x 8..12 -> corners at x 6 and 14 (2 m outside).
  const auto& first = plan.subgroups[0].firstMeeting;
  EXPECT_TRUE(first.place.isApprox(Vec3(6, -4, 0)));
  EXPECT_NEAR(first.time, 100.0 + 60.0 + std::hypot(6.0, 4.0) + 20.0, 1e-9);
  const auto& second = plan.subgroups[1].firstMeeting;
  EXPECT_TRUE(second.place.isApprox(Vec3(16, -4, 0)));
  EXPECT_NEAR(second.time, first.time + 10.0 + 20.0, 1e-9);
}

// Several stations (the paper's multi-GCS): explorers and inspectors in blocks in fleet order,
// boxes in strips along x by volume, each station planning its own subgroups from its boxes.
TEST(SleiFleetPlan, SeveralStationsShareExplorersInspectorsAndBoxStrips) {
  std::vector<agent::FleetMember> fleet{
      {"gcs1", agent::Role::GroundStation}, {"gcs2", agent::Role::GroundStation},
      {"e1", agent::Role::Explorer},        {"e2", agent::Role::Explorer},
      {"e3", agent::Role::Explorer},        {"i1", agent::Role::Photographer},
      {"i2", agent::Role::Photographer},    {"i3", agent::Role::Photographer},
      {"i4", agent::Role::Photographer},    {"i5", agent::Role::Photographer},
      {"i6", agent::Role::Photographer}};
  // Along x (the longer spread): 0, 10, 20, 30, 40, the box at 30 twice the volume.
  const std::vector<agent::BoxView> boxes{
      makeBox({40, 0, 5}, {4, 4, 10}), makeBox({0, 2, 5}, {4, 4, 10}),
      makeBox({30, -2, 5}, {4, 8, 10}), makeBox({10, 0, 5}, {4, 4, 10}),
      makeBox({20, 0, 5}, {4, 4, 10})};
  const auto shares = stationShares(fleet, boxes);
  ASSERT_EQ(shares.size(), 2u);
  EXPECT_EQ(shares[0].station, 0u);
  EXPECT_EQ(shares[1].station, 1u);
  EXPECT_EQ(shares[0].explorers, (std::vector<uint32_t>{2, 3}));  // the first gets one more
  EXPECT_EQ(shares[1].explorers, (std::vector<uint32_t>{4}));
  EXPECT_EQ(shares[0].inspectors, (std::vector<uint32_t>{5, 6, 7, 8}));  // 2/3 of 6
  EXPECT_EQ(shares[1].inspectors, (std::vector<uint32_t>{9, 10}));
  // Volumes 1, 1, 1, 2, 1 (of 6) in x order; the first station's share is 2/3, 4 of 6: the
  // middles at 0.5, 1.5 and 2.5 fall in it, the double box's at 4 does not (a box is one
  // station's: the boundary fell in it).
  EXPECT_EQ(shares[0].boxes, (std::vector<uint8_t>{0, 1, 0, 1, 1}));
  EXPECT_EQ(shares[1].boxes, (std::vector<uint8_t>{1, 0, 1, 0, 0}));
  const auto second = makeFleetPlan(shares[1], boxes, Vec3(40, -20, 0.1), 0.0, 0.0, PlanOptions{});
  ASSERT_EQ(second.subgroups.size(), 1u);
  EXPECT_EQ(second.subgroups[0].explorer, 4u);
  EXPECT_EQ(second.subgroups[0].station, 1u);
  EXPECT_EQ(second.subgroups[0].box, 0);
  EXPECT_EQ(second.subgroups[0].inspectors, (std::vector<uint32_t>{9, 10}));
  // The first station's explorers take its boxes only, though the others are nearer to it.
  const auto first = makeFleetPlan(shares[0], boxes, Vec3(45, 0, 0.1), 0.0, 0.0, PlanOptions{});
  ASSERT_EQ(first.subgroups.size(), 2u);
  EXPECT_EQ(first.subgroups[0].box, 4);
  EXPECT_EQ(first.subgroups[1].box, 3);
  // Fixed orders deal the station's own boxes only.
  const auto orders = fixedBoxOrders(boxes, {4, 3}, {1, 0, 1, 0, 0});
  EXPECT_EQ(orders[0], (std::vector<int32_t>{1}));
  EXPECT_TRUE(orders[1].empty());
}

// Heterogeneous explorers (the paper: longer range, larger boxes): the first boxes chosen by
// the nearest-first chain are dealt again by volume and range.
TEST(SleiFleetPlan, TheLongestRangeExplorerGetsTheLargestFirstBox) {
  std::vector<agent::FleetMember> fleet{{"gcs", agent::Role::GroundStation},
                                        {"e1", agent::Role::Explorer, 8.0},
                                        {"e2", agent::Role::Explorer, 5.0},
                                        {"i1", agent::Role::Photographer}};
  const std::vector<agent::BoxView> boxes{makeBox({10, 0, 5}, {4, 4, 10}),
                                          makeBox({20, 0, 5}, {8, 8, 10}),
                                          makeBox({40, 0, 5}, {4, 4, 10})};
  const auto shares = stationShares(fleet, boxes);
  EXPECT_EQ(shares[0].explorerRanges, (std::vector<double>{8.0, 5.0}));
  const auto plan = makeFleetPlan(shares[0], boxes, Vec3(0, 0, 0.1), 0.0, 0.0, PlanOptions{});
  ASSERT_EQ(plan.subgroups.size(), 2u);
  EXPECT_EQ(plan.subgroups[0].box, 1);  // e1, 8 m: the larger of the two nearest
  EXPECT_EQ(plan.subgroups[1].box, 0);
  // Equal ranges: the chain's order (e1 the nearest box).
  fleet[1].detectRange = 5.0;
  const auto same =
      makeFleetPlan(stationShares(fleet, boxes)[0], boxes, Vec3(0, 0, 0.1), 0.0, 0.0, {});
  EXPECT_EQ(same.subgroups[0].box, 0);
  EXPECT_EQ(same.subgroups[1].box, 1);
}

TEST(SleiFleetPlan, TheStationServesAnOverdueMeetingBeforeWaitingForALaterOne) {
  EXPECT_EQ(meetingToServe({}, 100.0), 0u);
  EXPECT_EQ(meetingToServe({90.0, 50.0}, 100.0), 0u);    // the first is due: it goes on
  EXPECT_EQ(meetingToServe({300.0, 200.0}, 100.0), 0u);  // nothing overdue
  // The first is not due before 700 s; two others were due at 95 and 80 s: the earliest first.
  EXPECT_EQ(meetingToServe({700.0, 95.0, 80.0}, 100.0), 2u);
}

TEST(SleiFleetPlan, TheUnknownWorkspaceIsTheBoxesBoundsInEqualSlabs) {
  // A 10 x 4 x 6 box at the origin and one turned by 90 deg: 2 x 8 x 4 at (20, 0, 1).
  std::vector<agent::BoxView> boxes = {makeBox(Vec3(0, 0, 3), Vec3(10, 4, 6)),
                                       makeBox(Vec3(20, 0, 1), Vec3(8, 2, 4), M_PI / 2)};
  const auto workspace = workspaceBox(boxes);
  EXPECT_TRUE(workspace.center.isApprox(Vec3(8, 0, 2.5), 1e-9)) << workspace.center.transpose();
  EXPECT_TRUE(workspace.size.isApprox(Vec3(26, 8, 7), 1e-9)) << workspace.size.transpose();
  // Across the longer side (x): three slabs of 26 / 3 m, in order along it.
  const auto slabs = splitWorkspace(workspace, 3);
  ASSERT_EQ(slabs.size(), 3u);
  for (size_t i = 0; i < 3; ++i) {
    EXPECT_NEAR(slabs[i].size.x(), 26.0 / 3.0, 1e-9);
    EXPECT_NEAR(slabs[i].size.y(), 8.0, 1e-9);
    EXPECT_NEAR(slabs[i].center.x(), -5.0 + (i + 0.5) * 26.0 / 3.0, 1e-9);
    EXPECT_NEAR(slabs[i].center.z(), 2.5, 1e-9);
  }
  // Longer along y: slabs across y.
  const auto tall = splitWorkspace(makeBox(Vec3(0, 0, 0), Vec3(4, 12, 2)), 2);
  ASSERT_EQ(tall.size(), 2u);
  EXPECT_NEAR(tall[0].center.y(), -3.0, 1e-9);
  EXPECT_NEAR(tall[1].size.y(), 6.0, 1e-9);
  EXPECT_TRUE(splitWorkspace(workspace, 0).empty());
}

TEST(SleiFleetPlan, TheOctreeStepHalvesEveryEdgeLongerThanTheLeafSize) {
  agent::BoxView box = makeBox(Vec3(0, 0, 5), Vec3(24, 16, 8));
  box.highPriority = true;
  // x and y above 10 m, z not: four parts of 12 x 8 x 8, x fastest.
  const auto parts = octreeChildren(box, 10.0);
  ASSERT_EQ(parts.size(), 4u);
  EXPECT_TRUE(parts[0].center.isApprox(Vec3(-6, -4, 5), 1e-9));
  EXPECT_TRUE(parts[1].center.isApprox(Vec3(6, -4, 5), 1e-9));
  EXPECT_TRUE(parts[3].center.isApprox(Vec3(6, 4, 5), 1e-9));
  double volume = 0.0;
  for (const auto& part : parts) {
    EXPECT_TRUE(part.size.isApprox(Vec3(12, 8, 8), 1e-9));
    EXPECT_TRUE(part.highPriority);
    volume += part.size.prod();
  }
  EXPECT_NEAR(volume, box.size.prod(), 1e-6);
  // Every edge above the leaf size: eight; none: nothing (a leaf).
  EXPECT_EQ(octreeChildren(makeBox(Vec3(0, 0, 0), Vec3(20, 20, 20)), 10.0).size(), 8u);
  EXPECT_TRUE(octreeChildren(parts[0], 12.0).empty());
}

TEST(SleiFleetPlan, ALostSubgroupsBoxGoesToTheShortestOtherOrder) {
  std::vector<std::vector<int32_t>> orders{{1, 2}, {3}, {4}};
  giveBoxToShortestOrder(orders, 1, 7);  // 1 is lost: 2 is the shortest of the others
  EXPECT_EQ(orders[2], (std::vector<int32_t>{4, 7}));
  giveBoxToShortestOrder(orders, 2, 8);  // 1 (one box) is shorter than 0 (two)
  EXPECT_EQ(orders[1], (std::vector<int32_t>{3, 8}));
  giveBoxToShortestOrder(orders, 2, 9);  // 0 and 1 both hold two: the lower index
  EXPECT_EQ(orders[0], (std::vector<int32_t>{1, 2, 9}));
  std::vector<std::vector<int32_t>> alone{{5}};
  giveBoxToShortestOrder(alone, 0, 6);  // nobody else: the box stays unexplored
  EXPECT_EQ(alone[0], (std::vector<int32_t>{5}));
}

}  // namespace
}  // namespace coinspect::strategies::slei
