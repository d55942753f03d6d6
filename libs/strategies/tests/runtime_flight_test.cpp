#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <memory>

#include "coinspect/strategies/runtime/flight.h"
#include "coinspect/strategies/runtime/robot_map.h"

namespace coinspect::strategies::runtime {
namespace {

BoxView makeBox(const Vec3& centre, const Vec3& size) {
  BoxView box;
  box.center = centre;
  box.size = size;
  return box;
}

// A key frame of a wall x = 0, |y| <= 8, 0 <= z <= 12, seen from `origin`.
agent::KeyFrameView wallFrame(const Vec3& origin) {
  auto frame = std::make_shared<agent::KeyFrame>();
  frame->producer = "scout";
  frame->position = origin;
  for (double y = -8.0; y <= 8.0; y += 0.25)
    for (double z = 0.0; z <= 12.0; z += 0.25)
      frame->points.emplace_back(0.0f, static_cast<float>(y), static_cast<float>(z));
  return frame;
}

RobotMapOptions mapOptions(UnknownSpace unknown) {
  RobotMapOptions options;
  options.gridResolution = 0.5;
  options.regionMargin = 10.0;
  options.rebuildPeriod = 1.0;
  options.unknown = unknown;
  return options;
}

TEST(RobotMap, NearBoxesPolicyBlocksUnknownOnlyNearTheBoxes) {
  const std::vector<BoxView> boxes{makeBox({0, 0, 10}, {4, 4, 8})};
  RobotMap map(mapOptions(UnknownSpace::BlockedNearBoxes), boxes, 0.0);
  const auto& grid = map.grid();
  EXPECT_EQ(grid.state(grid.cellOf({0, 0, 10})), mapping::CellState::Unknown);
  EXPECT_EQ(grid.state(grid.cellOf({0, 0, 3})), mapping::CellState::Unknown);  // under the box
  EXPECT_EQ(grid.state(grid.cellOf({8, 8, 10})), mapping::CellState::Free);
  EXPECT_LT(grid.clearance(grid.cellOf({0, 0, 10})), 0.01f);
  EXPECT_GT(grid.clearance(grid.cellOf({9, 9, 10})), 3.0f);

  RobotMap strict(mapOptions(UnknownSpace::Blocked), boxes, 0.0);
  EXPECT_EQ(strict.grid().state(strict.grid().cellOf({8, 8, 10})), mapping::CellState::Unknown);
}

TEST(RobotMap, InsertsKeyFramesAndRebuildsAtMostEveryPeriod) {
  const std::vector<BoxView> boxes{makeBox({0, 0, 6}, {1, 16, 12})};
  RobotMap map(mapOptions(UnknownSpace::BlockedNearBoxes), boxes, 0.0);
  const uint64_t first = map.gridVersion();
  EXPECT_FALSE(map.refresh(0.5));  // nothing new
  agent::AgentView view;
  view.receivedKeyFrames.push_back(wallFrame({-6, 0, 6}));
  map.update(view);
  EXPECT_EQ(map.scansInserted(), 1u);
  EXPECT_TRUE(map.refresh(0.5));
  EXPECT_EQ(map.gridVersion(), first + 1);
  const auto& grid = map.grid();
  EXPECT_EQ(grid.state(grid.cellOf({0.1, 0, 6})), mapping::CellState::Occupied);
  EXPECT_EQ(grid.state(grid.cellOf({-3, 0, 6})), mapping::CellState::Free);  // seen through
  map.update(view);
  EXPECT_FALSE(map.refresh(1.0));  // changed, but within the period
  EXPECT_TRUE(map.refresh(1.6));
}

// A perfect vehicle: it is where the last setpoint asked.
struct PerfectVehicle {
  agent::AgentView view;
  void apply(const agent::AgentSetpoint& setpoint, double dt) {
    view.odometry.velocity = setpoint.velocity;
    view.odometry.position = setpoint.position;
    view.time += dt;
  }
};

TEST(Flight, TakesOffThenGoesAroundAMappedWallKeepingItsClearance) {
  const std::vector<BoxView> boxes{makeBox({0, 0, 6}, {1, 16, 12})};
  auto options = mapOptions(UnknownSpace::BlockedNearBoxes);
  options.boxMargin = 0.5;
  RobotMap map(options, boxes, 0.0);
  agent::AgentView scan;
  scan.receivedKeyFrames.push_back(wallFrame({-6, 0, 6}));
  scan.receivedKeyFrames.push_back(wallFrame({6, 0, 6}));
  map.update(scan);
  map.refresh(0.0, true);

  FlightOptions flightOptions;
  flightOptions.radius = 0.3;
  flightOptions.safetyMargin = 0.5;
  flightOptions.takeoffHeight = 2.0;
  Flight flight(flightOptions, {"me"}, 0);
  PerfectVehicle vehicle;
  vehicle.view.name = "me";
  vehicle.view.odometry.position = Vec3(-6, 0, 0.1);
  flight.goTo(Vec3(6, 0, 4), 2.0);
  double nearest = 1e9;
  for (int i = 0; i < 1200 && !flight.done(); ++i) {
    const auto setpoint = flight.step(vehicle.view, map);
    vehicle.apply(setpoint, 0.1);
    const Vec3 p = vehicle.view.odometry.position;
    if (std::abs(p.y()) <= 8.0 && p.z() <= 12.0)
      nearest = std::min(nearest, std::abs(p.x()));
    else
      nearest = std::min(
          nearest,
          (p - Vec3(0, std::clamp(p.y(), -8.0, 8.0), std::clamp(p.z(), 0.0, 12.0))).norm());
    if (i == 10) {
      EXPECT_TRUE(flight.takingOff());
    }
  }
  EXPECT_TRUE(flight.done());
  EXPECT_FALSE(flight.failed());
  EXPECT_NEAR((vehicle.view.odometry.position - Vec3(6, 0, 4)).norm(), 0.0, 0.6);
  EXPECT_GE(nearest, flightOptions.radius + flightOptions.safetyMargin);
}

TEST(Flight, LowerPriorityHoldsForAHigherPriorityNeighbourOnItsPath) {
  const std::vector<BoxView> boxes{makeBox({0, 30, 6}, {2, 2, 2})};
  RobotMap map(mapOptions(UnknownSpace::BlockedNearBoxes), boxes, 0.0);
  FlightOptions flightOptions;
  flightOptions.takeoffHeight = 1.0;
  Flight flight(flightOptions, {"first", "second"}, 1);
  PerfectVehicle vehicle;
  vehicle.view.name = "second";
  vehicle.view.odometry.position = Vec3(0, 20, 4);
  for (int i = 0; i < 40; ++i)  // take off
    vehicle.apply(flight.step(vehicle.view, map), 0.1);
  flight.goTo(Vec3(0, 40, 5), 2.0);
  agent::NeighbourInfo other;
  other.name = "first";
  other.role = agent::Role::Photographer;
  other.odometry.position = Vec3(0, 23, 5);  // hovering 3 m ahead
  vehicle.view.neighbours.push_back(other);
  const Vec3 before = vehicle.view.odometry.position;
  for (int i = 0; i < 50; ++i)
    vehicle.apply(flight.step(vehicle.view, map), 0.1);
  EXPECT_LT((vehicle.view.odometry.position - before).norm(), 0.5);
  vehicle.view.neighbours.clear();  // it left
  for (int i = 0; i < 200 && !flight.done(); ++i)
    vehicle.apply(flight.step(vehicle.view, map), 0.1);
  EXPECT_TRUE(flight.done());
}

}  // namespace
}  // namespace coinspect::strategies::runtime
