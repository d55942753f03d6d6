#include <gtest/gtest.h>

#include <cmath>

#include "coinspect/strategies/runtime/path_profile.h"

namespace coinspect::strategies::runtime {
namespace {

TEST(PathProfile, RespectsSpeedAndAccelerationAndEndsAtRest) {
  ProfileLimits limits;
  limits.speed = 2.0;
  limits.acceleration = 1.0;
  limits.cornerSpeed = 0.5;
  PathProfile profile({{0, 0, 0}, {20, 0, 0}, {20, 20, 0}}, limits);
  EXPECT_NEAR(profile.length(), 40.0, 1e-12);
  EXPECT_NEAR(profile.speedAt(10.0), 2.0, 1e-12);             // cruising
  EXPECT_NEAR(profile.speedAt(20.0), 0.5, 1e-12);             // right-angle corner
  EXPECT_NEAR(profile.speedAt(40.0), 0.0, 1e-12);             // rest at the end
  EXPECT_NEAR(profile.speedAt(39.5), std::sqrt(1.0), 1e-12);  // braking at 1 m/s^2
  // A perfect vehicle riding the carrot arrives, never faster than the limit.
  Vec3 vehicle = Vec3::Zero();
  double previous = limits.cornerSpeed;  // it leaves the start at the corner speed
  int steps = 0;
  while (!profile.finished() && steps < 1000) {
    profile.advance(vehicle, 0.1);
    const auto setpoint = profile.setpoint();
    EXPECT_LE(setpoint.velocity.norm(), 2.0 + 1e-9);
    EXPECT_LE(std::abs(setpoint.velocity.norm() - previous), 0.1 * 1.0 + 0.06);
    previous = setpoint.velocity.norm();
    vehicle = setpoint.position;
    ++steps;
  }
  EXPECT_TRUE(profile.finished());
  EXPECT_NEAR((vehicle - Vec3(20, 20, 0)).norm(), 0.0, 1e-9);
  EXPECT_GT(steps, 200);  // 40 m at <= 2 m/s takes more than 20 s
}

TEST(PathProfile, WaitsForALaggingVehicle) {
  ProfileLimits limits;
  limits.maxLag = 1.0;
  PathProfile profile({{0, 0, 0}, {10, 0, 0}}, limits);
  for (int i = 0; i < 100; ++i)
    profile.advance(Vec3::Zero(), 0.1);  // the vehicle never moves
  EXPECT_LE(profile.travelled(), 1.0 + 0.3);
  EXPECT_FALSE(profile.finished());
  EXPECT_EQ(profile.nextVertex(), 1u);
  // While it waits it asks for no speed: a velocity feed-forward along the path would hold the
  // vehicle off at a balance between it and the position error, and the carrot would wait forever.
  EXPECT_EQ(profile.setpoint().velocity, Vec3::Zero());
  profile.advance(profile.pointAt(profile.travelled()), 0.1);  // it caught up
  EXPECT_GT(profile.setpoint().velocity.norm(), 0.0);
}

TEST(PathProfile, ASinglePointIsAHover) {
  PathProfile profile({{1, 2, 3}, {1, 2, 3}}, ProfileLimits{});
  EXPECT_TRUE(profile.finished());
  EXPECT_NEAR((profile.setpoint().position - Vec3(1, 2, 3)).norm(), 0.0, 1e-12);
  EXPECT_NEAR(profile.setpoint().velocity.norm(), 0.0, 1e-12);
}

}  // namespace
}  // namespace coinspect::strategies::runtime
