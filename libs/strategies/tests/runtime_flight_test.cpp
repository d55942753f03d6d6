#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <memory>

#include "coinspect/strategies/runtime/flight.h"
#include "coinspect/strategies/runtime/robot_map.h"
#include "test_boxes.h"

namespace coinspect::strategies::runtime {
namespace {

using test::makeBox;

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

// A wall x = 0, |y| <= 8, 0 <= z <= 12 inside its box, mapped from both sides.
RobotMap wallMap() {
  const std::vector<BoxView> boxes{makeBox({0, 0, 6}, {1, 16, 12})};
  auto options = mapOptions(UnknownSpace::BlockedNearBoxes);
  options.boxMargin = 0.5;
  RobotMap map(options, boxes, 0.0);
  agent::AgentView scan;
  scan.receivedKeyFrames.push_back(wallFrame({-6, 0, 6}));
  scan.receivedKeyFrames.push_back(wallFrame({6, 0, 6}));
  map.update(scan);
  map.refresh(0.0, true);
  return map;
}

TEST(Flight, TakesOffThenGoesAroundAMappedWallKeepingItsClearance) {
  const auto map = wallMap();

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

TEST(Flight, AGoalItHoldsAtIsNotFlownAgain) {
  // Callers ask for their goal at every decision; at a reached goal that planned a path from
  // the goal to itself each time, and done() was never true when they looked (an inspector's
  // patience at a pose never started).
  const auto map = wallMap();
  Flight flight(FlightOptions{}, {"me"}, 0);
  PerfectVehicle vehicle;
  vehicle.view.name = "me";
  vehicle.view.odometry.position = Vec3(-6, 0, 0.1);
  const Vec3 goal(-6, -4, 5);
  flight.goTo(goal, 2.0);
  for (int i = 0; i < 400 && !flight.done(); ++i)
    vehicle.apply(flight.step(vehicle.view, map), 0.1);
  ASSERT_TRUE(flight.done());
  const Vec3 there = vehicle.view.odometry.position;
  for (int i = 0; i < 20; ++i) {
    flight.goTo(goal + Vec3(0.1, 0, 0), 2.0);
    EXPECT_TRUE(flight.done()) << i;
    const auto setpoint = flight.step(vehicle.view, map);
    EXPECT_EQ(setpoint.position, there) << i;
    vehicle.apply(setpoint, 0.1);
  }
  // After a hover (or any other goal) the same goal is a new flight.
  flight.hover();
  flight.goTo(goal, 2.0);
  EXPECT_FALSE(flight.done());
}

// Flies from (-6, 0, 0.1) toward `goal` for `steps` decisions of 0.1 s after taking off.
void takeOffAndFly(Flight* flight, PerfectVehicle* vehicle, const RobotMap& map, const Vec3& goal,
                   int steps) {
  vehicle->view.name = "me";
  vehicle->view.odometry.position = Vec3(-6, 0, 0.1);
  for (int i = 0; i < 200 && !flight->done(); ++i)
    vehicle->apply(flight->step(vehicle->view, map), 0.1);
  ASSERT_TRUE(flight->done());
  flight->goTo(goal, 2.0);
  for (int i = 0; i < steps; ++i)
    vehicle->apply(flight->step(vehicle->view, map), 0.1);
}

TEST(Flight, HoldsWhereItIsWhenANewRouteCannotBePlannedInFlight) {
  // A mission lost a unit this way: a new goal given in flight could not be planned, and the
  // unit held at the point where it had last stopped, 50 m back, flying straight at it.
  const auto map = wallMap();
  Flight flight(FlightOptions{}, {"me"}, 0);
  PerfectVehicle vehicle;
  takeOffAndFly(&flight, &vehicle, map, Vec3(-6, -7, 10), 50);
  const Vec3 there = vehicle.view.odometry.position;
  ASSERT_GT((there - Vec3(-6, 0, 3.1)).norm(), 4.0);  // far from the take-off point
  flight.follow({Vec3(500, 0, 5)}, 2.0);              // outside the map: cannot be planned
  for (int i = 0; i < 30; ++i) {
    const auto setpoint = flight.step(vehicle.view, map);
    EXPECT_LT((setpoint.position - vehicle.view.odometry.position).norm(), 1.0) << i;
    vehicle.apply(setpoint, 0.1);
  }
  EXPECT_LT((vehicle.view.odometry.position - there).norm(), 1.0);
  EXPECT_EQ(flight.guardedSetpoints(), 0u);  // the hold point itself was right
}

TEST(Flight, NeverSendsASetpointFarFromTheVehicleOrAcrossAWall) {
  const auto map = wallMap();
  FlightOptions options;
  Flight flight(options, {"me"}, 0);
  PerfectVehicle vehicle;
  takeOffAndFly(&flight, &vehicle, map, Vec3(-6, -7, 10), 30);
  ASSERT_FALSE(flight.done());
  const Vec3 carrot = flight.profile().setpoint().position;
  // A gust puts the vehicle 6 m aside in open space: the carrot waits, the setpoint moves toward
  // it by at most maxSetpointOffset, with no velocity feed-forward.
  vehicle.view.odometry.position = carrot + Vec3(0, -6, 0);
  auto setpoint = flight.step(vehicle.view, map);
  EXPECT_NEAR((setpoint.position - vehicle.view.odometry.position).norm(),
              options.maxSetpointOffset, 1e-9);
  EXPECT_LT((setpoint.position - carrot).norm(), 6.0 - options.maxSetpointOffset + 1e-9);
  EXPECT_EQ(setpoint.velocity, Vec3::Zero());
  EXPECT_EQ(flight.guardedSetpoints(), 1u);
  // Behind the wall (x > 0) the straight line to the carrot crosses it: hold where it is.
  vehicle.view.odometry.position = Vec3(1.5, carrot.y(), carrot.z());
  setpoint = flight.step(vehicle.view, map);
  EXPECT_EQ(setpoint.position, vehicle.view.odometry.position);
  EXPECT_EQ(flight.guardedSetpoints(), 2u);
  // It does not wait there for a reference point it cannot reach: it plans again around the wall.
  vehicle.apply(setpoint, 0.1);
  for (int i = 0; i < 600 && !flight.done(); ++i)
    vehicle.apply(flight.step(vehicle.view, map), 0.1);
  EXPECT_TRUE(flight.done());
  EXPECT_LT((vehicle.view.odometry.position - Vec3(-6, -7, 10)).norm(), 0.6);
  EXPECT_EQ(flight.guardedSetpoints(), 2u);
}

// A corridor along y between walls x = -halfWidth(y) and x = +halfWidth(y), 0 <= z <= 12,
// |y| <= 8, under a roof at z = 12, mapped; unknown space is free (the test is about the walls).
RobotMap corridorMap(double (*halfWidth)(double y)) {
  RobotMap map(mapOptions(UnknownSpace::Free), {makeBox({0, 0, 6}, {6, 16, 12})}, 0.0);
  agent::AgentView scan;
  for (const double side : {-1.0, 1.0}) {
    auto frame = std::make_shared<agent::KeyFrame>();
    frame->producer = "scout";
    frame->position = Vec3(0, 0, 6);
    for (double y = -8.0; y <= 8.0; y += 0.25)
      for (double z = 0.0; z <= 12.0; z += 0.25)
        frame->points.emplace_back(static_cast<float>(side * halfWidth(y)), static_cast<float>(y),
                                   static_cast<float>(z));
    scan.receivedKeyFrames.push_back(frame);
  }
  auto roof = std::make_shared<agent::KeyFrame>();
  roof->producer = "scout";
  roof->position = Vec3(0, 0, 6);
  for (double y = -8.0; y <= 8.0; y += 0.25)
    for (double x = -halfWidth(y); x <= halfWidth(y); x += 0.25)
      roof->points.emplace_back(static_cast<float>(x), static_cast<float>(y), 12.0f);
  scan.receivedKeyFrames.push_back(roof);
  map.update(scan);
  map.refresh(0.0, true);
  return map;
}

// Flies from (0, 0, 5) to (0, 14, 6), beyond the corridor's end, and checks it got there without
// coming closer to a wall than its own radius.
void leaveCorridor(const RobotMap& map, double (*halfWidth)(double y)) {
  FlightOptions options;
  options.takeoffHeight = 1.0;
  Flight flight(options, {"me"}, 0);
  PerfectVehicle vehicle;
  vehicle.view.name = "me";
  vehicle.view.odometry.position = Vec3(0, 0, 5);
  const Vec3 goal(0, 14, 6);
  flight.goTo(goal, 2.0);
  double nearestWall = 1e9;
  for (int i = 0; i < 600 && !flight.done(); ++i) {
    vehicle.apply(flight.step(vehicle.view, map), 0.1);
    const Vec3 p = vehicle.view.odometry.position;
    if (std::abs(p.y()) <= 8.0)
      nearestWall = std::min(nearestWall, halfWidth(p.y()) - std::abs(p.x()));
  }
  EXPECT_TRUE(flight.done());
  EXPECT_FALSE(flight.failed());
  EXPECT_LT((vehicle.view.odometry.position - goal).norm(), 0.6);
  EXPECT_GE(nearestWall, options.radius);
}

TEST(Flight, LeavesAPlaceNarrowerThanItsClearanceAtTheClearanceOfItsOwnSphere) {
  // A unit is closer than radius + margin to a wall wherever it is in a 3 m corridor, with no
  // clear cell within the snap radius: it used to fail every plan and stay there for good.
  const auto narrow = [](double) { return 1.5; };
  const auto map = corridorMap(narrow);
  const auto& grid = map.grid();
  ASSERT_LT(grid.clearance(grid.cellOf({0, 0, 6})), Flight({}, {"me"}, 0).requiredClearance(grid));
  leaveCorridor(map, narrow);
}

TEST(Flight, LeavesAPocketOfItsClearanceAtTheClearanceOfItsOwnSphere) {
  // 5.5 m wide in the middle, where the unit has its clearance, 3 m at both ends, where it does
  // not: a pocket (an explorer spent most of a mission in one, every plan out failing).
  const auto pocket = [](double y) { return std::abs(y) <= 5.0 ? 2.75 : 1.5; };
  const auto map = corridorMap(pocket);
  const auto& grid = map.grid();
  const double required = Flight({}, {"me"}, 0).requiredClearance(grid);
  ASSERT_GE(grid.clearance(grid.cellOf({0, 0, 5})), required);  // where it starts
  ASSERT_LT(grid.clearance(grid.cellOf({0, 7, 6})), required);
  leaveCorridor(map, pocket);
}

// Units "first" and "second" (fleet order) by a small box; unit `self` has climbed 1 m from
// (0, 22, 4), well inside the map's region, and is about to fly.
struct TwoUnits {
  TwoUnits(const Vec3& boxCentre, size_t self)
      : map(wideMapOptions(), {makeBox(boxCentre, {2, 2, 2})}, 0.0),
        flight(options(), {"first", "second"}, self) {
    vehicle.view.name = self == 0 ? "first" : "second";
    vehicle.view.odometry.position = Vec3(0, 22, 4);
    for (int i = 0; i < 40; ++i)
      step();
  }
  static RobotMapOptions wideMapOptions() {
    auto o = mapOptions(UnknownSpace::BlockedNearBoxes);
    o.regionMargin = 20.0;
    return o;
  }
  static FlightOptions options() {
    FlightOptions o;
    o.takeoffHeight = 1.0;
    return o;
  }
  // The other unit, at `position`, hovering or moving at `velocity`.
  void addOther(const Vec3& position, const Vec3& velocity = Vec3::Zero()) {
    agent::NeighbourInfo other;
    other.name = vehicle.view.name == "first" ? "second" : "first";
    other.role = agent::Role::Photographer;
    other.odometry.position = position;
    other.odometry.velocity = velocity;
    vehicle.view.neighbours.push_back(other);
  }
  void step() { vehicle.apply(flight.step(vehicle.view, map), 0.1); }

  RobotMap map;
  Flight flight;
  PerfectVehicle vehicle;
};

TEST(Flight, LowerPriorityHoldsForAHigherPriorityNeighbourOnItsPath) {
  TwoUnits units({0, 30, 6}, 1);
  units.flight.goTo(Vec3(0, 40, 5), 2.0);
  const Vec3 other(0, 25, 5);
  units.addOther(other, Vec3(0.5, 0, 0));  // 3 m ahead, moving across
  // It does not fly on; it backs off to `separation`, out of the other's way.
  for (int i = 0; i < 50; ++i) {
    units.step();
    EXPECT_GE((units.vehicle.view.odometry.position - other).norm(), 3.0 - 1e-9) << i;
  }
  const double separation = TwoUnits::options().separation;
  const double distance = (units.vehicle.view.odometry.position - other).norm();
  EXPECT_GE(distance, separation);
  EXPECT_LE(distance, separation + 1.5);  // one escape step at most beyond
  units.vehicle.view.neighbours.clear();  // it left
  for (int i = 0; i < 200 && !units.flight.done(); ++i)
    units.step();
  EXPECT_TRUE(units.flight.done());
}

// An explorer charging above its station (slei-b): the other explorer passing within the hold
// distance pushed it out of the charger's range. Standing its ground it stays put, and only
// closer than minSeparation does it still back away.
TEST(Flight, StandingItsGroundItNeitherHoldsNorBacksOffForAHigherPriorityNeighbour) {
  for (const bool stand : {false, true}) {
    TwoUnits units({0, 10, 6}, 1);  // the box far away
    ASSERT_TRUE(units.flight.done());
    const Vec3 hold = units.vehicle.view.odometry.position;
    units.flight.standGround(stand);
    units.addOther(hold + Vec3(3, 0, 0));  // between minSeparation and separation
    for (int i = 0; i < 50; ++i)
      units.step();
    const double moved = (units.vehicle.view.odometry.position - hold).norm();
    if (stand)
      EXPECT_LT(moved, 1e-6);
    else
      EXPECT_GT(moved, 0.5);  // backed off toward `separation`
  }
  TwoUnits units({0, 10, 6}, 1);
  const Vec3 hold = units.vehicle.view.odometry.position;
  units.flight.standGround(true);
  units.addOther(hold + Vec3(1, 0, 0));  // closer than minSeparation
  for (int i = 0; i < 20; ++i)
    units.step();
  EXPECT_GT((units.vehicle.view.odometry.position - hold).norm(), 0.5);
}

TEST(Flight, LowerPriorityGoesAroundAHigherPriorityNeighbourThatStaysOnItsPath) {
  // Two inspectors of slei-b: the second held behind the first, waiting at its own wait point,
  // for the rest of a run.
  TwoUnits units({9, 30, 6}, 1);  // the box off the straight line
  const Vec3 goal(0, 40, 5), other(0, 27, 5);
  units.flight.goTo(goal, 2.0);
  units.addOther(other);  // hovering on the straight line
  const auto options = TwoUnits::options();
  double nearest = 1e9;
  for (int i = 0; i < 600 && !units.flight.done(); ++i) {
    units.step();
    nearest = std::min(nearest, (units.vehicle.view.odometry.position - other).norm());
  }
  EXPECT_TRUE(units.flight.done());
  EXPECT_LT((units.vehicle.view.odometry.position - goal).norm(), 0.6);
  EXPECT_GE(nearest, options.separation - 1.5);  // around it, not through its hold distance
}

TEST(Flight, HigherPriorityStopsShortOfALowerPriorityUnitInItsWayThenGoesAround) {
  // A mission lost two units this way: the higher-priority one flew its path through a
  // lower-priority one that was holding for it, until both backed away and came back.
  TwoUnits units({9, 30, 6}, 0);  // the box off the straight line
  const Vec3 goal(0, 40, 5), other(0, 27, 5);
  units.flight.goTo(goal, 2.0);
  units.addOther(other);  // holding on the straight line
  const auto options = TwoUnits::options();
  double nearest = 1e9;
  double stoppedFor = 0.0;
  for (int i = 0; i < 400 && !units.flight.done(); ++i) {
    const Vec3 before = units.vehicle.view.odometry.position;
    units.step();
    const Vec3 p = units.vehicle.view.odometry.position;
    nearest = std::min(nearest, (p - other).norm());
    if ((p - before).norm() < 1e-6 && p.y() > 22.5 && p.y() < 27.0) stoppedFor += 0.1;
  }
  EXPECT_TRUE(units.flight.done());
  EXPECT_LT((units.vehicle.view.odometry.position - goal).norm(), 0.6);
  EXPECT_GE(nearest, options.minSeparation + options.radius - 1e-9);
  // It waited for the other to get out of the way before it went around.
  EXPECT_GE(stoppedFor, options.yieldPatience - 0.2);
  EXPECT_FALSE(units.flight.failed());
}

// Points every 0.25 m on the rectangle spanned by `side1` and `side2` from `corner`, as a key
// frame seen from `origin`, inserted into the units' map.
void addSurface(TwoUnits* units, const Vec3& origin, const Vec3& corner, const Vec3& side1,
                const Vec3& side2) {
  auto frame = std::make_shared<agent::KeyFrame>();
  frame->producer = "scout";
  frame->position = origin;
  for (double a = 0.0; a <= 1.0 + 1e-9; a += 0.25 / side1.norm())
    for (double b = 0.0; b <= 1.0 + 1e-9; b += 0.25 / side2.norm())
      frame->points.push_back((corner + a * side1 + b * side2).cast<float>());
  agent::AgentView scan;
  scan.receivedKeyFrames.push_back(frame);
  units->map.update(scan);
  units->map.refresh(units->vehicle.view.time, true);
}

TEST(Flight, BacksOffFromAHigherPriorityNeighbourEvenWithinItsMarginsOfASurface) {
  // slei-a, scene seed 2: two inspectors waiting within their path margins of mapped surface
  // could not step away from an explorer (the step was checked with those margins from a cell
  // that did not have them), and held it between them for 900 s.
  TwoUnits units({20, 40, 6}, 1);
  ASSERT_TRUE(units.flight.done());
  const Vec3 here = units.vehicle.view.odometry.position;  // (0, 22, 5)
  // A wall appears 1.2 m away: more than the unit's radius and half a cell, less than the
  // clearance paths keep.
  addSurface(&units, Vec3(-6, 22, 6), Vec3(1.2, 14, 0), Vec3(0, 16, 0), Vec3(0, 0, 12));
  const auto& grid = units.map.grid();
  ASSERT_LT(grid.clearance(grid.cellOf(here)), units.flight.requiredClearance(grid));
  units.addOther(here + Vec3(0, 3, 0));  // higher priority, 3 m away along the wall
  for (int i = 0; i < 30; ++i)
    units.step();
  EXPECT_GE((units.vehicle.view.odometry.position - here).norm(), 1.0);
  EXPECT_GE((units.vehicle.view.odometry.position - (here + Vec3(0, 3, 0))).norm(),
            TwoUnits::options().separation);
}

TEST(Flight, HoldsItsPointWhenItCannotBackOffFromAHigherPriorityNeighbour) {
  // slei-c, scene seed 1: an inspector hovering within its clearance of a structure, a
  // higher-priority teammate 2.5 m away. Backing off meant flying toward the structure, so it
  // held "where it is" at every decision: each hold followed the vehicle's own drift, and it slid
  // 3 m in 290 s until it hit the structure.
  TwoUnits units({0, 19.5, 5}, 1);  // box face at y = 20.5: the unit, at y = 22, is too close
  ASSERT_TRUE(units.flight.done());
  const Vec3 hold = units.vehicle.view.odometry.position;
  units.addOther(hold + Vec3(0, 3, 0));  // between minSeparation and separation, away from the box
  const Vec3 drift(0, -0.005, -0.002);   // per decision, toward the box and down
  for (int i = 0; i < 300; ++i) {
    units.step();
    units.vehicle.view.odometry.position += drift;
  }
  // A perfect vehicle sits where it was told to plus one decision's drift.
  EXPECT_LT((units.vehicle.view.odometry.position - hold).norm(), drift.norm() + 1e-9);
}

TEST(Flight, BacksOffAlongASurfaceRatherThanTowardAnother) {
  // slei-a, scene seed 4: an explorer backing off from a higher-priority one, its way away
  // blocked by a hall, stepped up under the hall's roof and then down, again and again; one
  // step up left it 0.2 m under an eave not mapped yet, which it hit as it was seen.
  TwoUnits units({20, 40, 6}, 1);
  ASSERT_TRUE(units.flight.done());
  const Vec3 here = units.vehicle.view.odometry.position;  // (0, 22, 5)
  const double ceiling = here.z() + 2.6;
  // A wall 1.7 m away in the direction away from the neighbour, a ceiling 2.6 m above.
  addSurface(&units, here, Vec3(-10, here.y() + 1.7, 0), Vec3(20, 0, 0), Vec3(0, 0, 12));
  addSurface(&units, here, Vec3(-10, here.y() - 10, ceiling), Vec3(20, 0, 0), Vec3(0, 11.7, 0));
  const Vec3 other = here + Vec3(0, -3, 0);
  units.addOther(other);  // higher priority
  double below = ceiling - here.z();
  for (int i = 0; i < 60; ++i) {
    units.step();
    below = std::min(below, ceiling - units.vehicle.view.odometry.position.z());
  }
  // Along the wall, not up toward the ceiling (the step up is clear of its own sphere), and out
  // to `separation` all the same.
  EXPECT_GE(below, ceiling - here.z() - 1e-9);
  EXPECT_GE((units.vehicle.view.odometry.position - other).norm(), TwoUnits::options().separation);
}

TEST(Flight, AHoverPointNewMapInformationBlocksBecomesWhereTheVehicleIs) {
  // The same explorer: its hover point was 0.2 m under the eave when the eave was mapped, 0.3 s
  // before the vehicle, climbing to it, hit it.
  TwoUnits units({20, 40, 6}, 1);
  ASSERT_TRUE(units.flight.done());
  const Vec3 hover = units.vehicle.view.odometry.position;
  units.vehicle.view.odometry.position = hover - Vec3(0, 0, 1.5);  // still climbing to it
  units.step();
  EXPECT_LT((units.vehicle.view.odometry.position - hover).norm(), 1e-9);  // flies to it
  units.vehicle.view.odometry.position = hover - Vec3(0, 0, 1.5);
  // A roof 0.2 m above the hover point.
  addSurface(&units, hover - Vec3(0, 0, 1.5), hover + Vec3(-5, -5, 0.2), Vec3(10, 0, 0),
             Vec3(0, 10, 0));
  units.step();
  EXPECT_LT((units.vehicle.view.odometry.position - (hover - Vec3(0, 0, 1.5))).norm(), 1e-9);
  // Later map updates leave that point alone (it is clear): no following the vehicle's drift.
  const Vec3 held = units.vehicle.view.odometry.position;
  addSurface(&units, held, held + Vec3(-5, 20, -5), Vec3(10, 0, 0), Vec3(0, 0, 10));
  units.vehicle.view.odometry.position += Vec3(0.1, 0, 0);
  units.step();
  EXPECT_LT((units.vehicle.view.odometry.position - held).norm(), 1e-9);
}

TEST(Flight, AStepAwayFromOneNeighbourDoesNotTakeItIntoAnother) {
  // 75 robots on slei-a (5 stations, 10 explorers, 60 inspectors 3 m apart): an inspector
  // backing off from a higher-priority one stepped into a lower-priority one, and both died 9 s
  // after take-off.
  TwoUnits units({20, 40, 6}, 1);
  ASSERT_TRUE(units.flight.done());
  const Vec3 here = units.vehicle.view.odometry.position;
  const Vec3 higher = here + Vec3(0, -3, 0), lower = here + Vec3(0, 2.6, 0);
  units.addOther(higher);  // "first"
  agent::NeighbourInfo third;
  third.name = "third";  // not in the flight's fleet: the lowest priority
  third.role = agent::Role::Photographer;
  third.odometry.position = lower;
  units.vehicle.view.neighbours.push_back(third);
  const auto options = TwoUnits::options();
  for (int i = 0; i < 30; ++i) {
    units.step();
    EXPECT_GE((units.vehicle.view.odometry.position - lower).norm(), options.minSeparation - 1e-9)
        << i;
  }
  EXPECT_GE((units.vehicle.view.odometry.position - higher).norm(), options.separation);
}

}  // namespace
}  // namespace coinspect::strategies::runtime
