#include "coinspect/vehicle/ground_vehicle.h"

#include <gtest/gtest.h>

#include <cmath>

#include "coinspect/core/error.h"

namespace coinspect::vehicle {
namespace {

TEST(GroundVehicle, StaticStationNeverMoves) {
  GroundVehicle station(Vec3(1, 2, 0), 0.0, 0.0);
  EXPECT_TRUE(station.setTarget(Vec3(50, 0, 0)));
  for (int i = 0; i < 100; ++i)
    station.advance(0.1);
  EXPECT_EQ(station.state().position, Vec3(1, 2, 0));
  EXPECT_FALSE(station.airborne());
}

TEST(GroundVehicle, DrivesAtMostItsSpeedAndStopsOnTheTarget) {
  GroundVehicle gcs(Vec3(0, 0, 0.2), 0.0, 1.0);
  gcs.setTarget(Vec3(0, 10, 5));  // z is ignored: it keeps its height
  for (int i = 0; i < 1200; ++i)
    gcs.advance(0.0025);  // 3 s at 1 m/s
  EXPECT_NEAR(gcs.state().position.y(), 3.0, 1e-9);
  EXPECT_NEAR(gcs.state().velocity.norm(), 1.0, 1e-12);
  EXPECT_NEAR(gcs.state().yaw, M_PI / 2, 1e-12);
  EXPECT_DOUBLE_EQ(gcs.state().position.z(), 0.2);
  for (int i = 0; i < 4000; ++i)
    gcs.advance(0.0025);
  EXPECT_EQ(gcs.state().position, Vec3(0, 10, 0.2));
  EXPECT_EQ(gcs.state().velocity, Vec3::Zero());
}

TEST(GroundVehicle, StopAtPutsItBackAtRestWithoutATarget) {
  GroundVehicle gcs(Vec3(0, 0, 0.2), 0.0, 1.0);
  gcs.setTarget(Vec3(10, 0, 0));
  gcs.advance(1.0);
  gcs.stopAt(Vec3(0.5, 0, 0.2));
  EXPECT_EQ(gcs.state().position, Vec3(0.5, 0, 0.2));
  EXPECT_EQ(gcs.state().velocity, Vec3::Zero());
  EXPECT_EQ(gcs.obstacleStops(), 1);
  gcs.advance(1.0);  // no target left: it stays
  EXPECT_EQ(gcs.state().position, Vec3(0.5, 0, 0.2));
  gcs.setTarget(Vec3(0.5, 2, 0));  // a new one moves it again
  gcs.advance(1.0);
  EXPECT_NEAR(gcs.state().position.y(), 1.0, 1e-12);
}

TEST(GroundVehicle, RejectsBadInput) {
  EXPECT_THROW(GroundVehicle(Vec3::Zero(), 0.0, -1.0), InputError);
  GroundVehicle gcs(Vec3::Zero(), 0.0, 1.0);
  EXPECT_FALSE(gcs.setTarget(Vec3(NAN, 0, 0)));
  EXPECT_EQ(gcs.rejectedCommands(), 1);
  gcs.advance(1.0);
  EXPECT_EQ(gcs.state().position, Vec3::Zero());
}

}  // namespace
}  // namespace coinspect::vehicle
