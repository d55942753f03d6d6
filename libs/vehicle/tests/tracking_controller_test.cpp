#include "coinspect/vehicle/tracking_controller.h"

#include <gtest/gtest.h>

#include <cmath>

#include "flight.h"

namespace coinspect::vehicle {
namespace {

using testing::kDegree;
using testing::shippedAirframe;

constexpr double kG = 9.81;

VehicleState levelAt(const Vec3& position, double time) {
  VehicleState s;
  s.position = position;
  s.time = time;
  return s;
}

TEST(TrackingController, IdleUntilTheFirstCommand) {
  TrackingController controller(shippedAirframe("explorer"));
  EXPECT_FALSE(controller.tick(0.0, levelAt(Vec3(0, 0, 0.1), 0.0)).has_value());
  EXPECT_EQ(controller.memory().mode, ControlMode::Idle);
}

TEST(TrackingController, HoverAtTheReferenceNeedsExactlyWeight) {
  const Airframe& airframe = shippedAirframe("explorer");
  TrackingController controller(airframe);
  controller.setCommand(positionSetpoint(Vec3(1, 2, 3), 0.0), 0.0);
  const auto out = controller.tick(0.0, levelAt(Vec3(1, 2, 3), 0.0));
  ASSERT_TRUE(out.has_value());
  // Zero errors: a = (0, 0, g); thrust = m g along the level body z.
  EXPECT_DOUBLE_EQ(out->thrust, airframe.mass * kG);
  EXPECT_DOUBLE_EQ(out->roll, 0.0);
  EXPECT_DOUBLE_EQ(out->pitch, 0.0);
  EXPECT_DOUBLE_EQ(out->yawRate, 0.0);
}

TEST(TrackingController, LargeErrorSaturatesAccelerationThenTilt) {
  // 100 m ahead in x: w^2 e = 400 is clamped to 10 m/s^2, z keeps g, so the wanted pitch is
  // atan(10 / 9.81) = 45.55 deg: clamped to 45 deg on the explorer, kept on the photographer.
  for (const char* name : {"explorer", "photographer"}) {
    const Airframe& airframe = shippedAirframe(name);
    TrackingController controller(airframe);
    controller.setCommand(positionSetpoint(Vec3(100, 0, 10), 0.0), 0.0);
    const auto out = controller.tick(0.0, levelAt(Vec3(0, 0, 10), 0.0));
    ASSERT_TRUE(out.has_value());
    const double wanted = std::atan2(10.0, kG);
    EXPECT_NEAR(out->pitch, std::min(wanted, airframe.tiltLimit), 1e-12) << name;
    EXPECT_NEAR(out->roll, 0.0, 1e-12);
    // Thrust projects the command on the current (level) body z: m * a_z = m g (integral: the
    // z error is zero, x has no effect on z).
    EXPECT_NEAR(out->thrust, airframe.mass * kG, 1e-9);
  }
}

TEST(TrackingController, IntegralAddsOneErrorPerTickAndIsClamped) {
  const Airframe& airframe = shippedAirframe("explorer");
  TrackingController controller(airframe);
  const VehicleState state = levelAt(Vec3(0, 0, 10), 0.0);
  for (int k = 0; k < 5; ++k) {
    controller.setCommand(positionSetpoint(Vec3(0, 0, 10.3), 0.0), k * kControlPeriod);
    controller.tick(k * kControlPeriod, state);
  }
  EXPECT_NEAR(controller.memory().positionErrorSum.z(), 5 * 0.3, 1e-12);
  for (int k = 5; k < 100; ++k) {
    controller.setCommand(positionSetpoint(Vec3(0, 0, 10.3), 0.0), k * kControlPeriod);
    controller.tick(k * kControlPeriod, state);
  }
  EXPECT_DOUBLE_EQ(controller.memory().positionErrorSum.z(), airframe.integralClamp);
}

TEST(TrackingController, ZeroPositionMeansVelocityControlWithTheReferenceIntegral) {
  const Airframe& airframe = shippedAirframe("explorer");
  TrackingController controller(airframe);
  controller.setCommand(velocitySetpoint(Vec3(1, 0, 0), 0.0), 0.0);
  const auto out = controller.tick(0.0, levelAt(Vec3(3, 0, 10), 0.0));
  ASSERT_TRUE(out.has_value());
  // No position term; damping 2 zeta w (1 - 0) = 4; the integral still adds (0 - p) as in the
  // reference: x sum -3 (ki 0.03 -> -0.09), z sum -10 after clamping (ki 0.07 -> -0.7).
  const double ax = 4.0 - 0.09;
  const double az = kG - 0.7;
  EXPECT_NEAR(out->pitch, std::atan2(ax, az), 1e-12);
  EXPECT_NEAR(out->thrust, airframe.mass * az, 1e-9);
}

TEST(TrackingController, AllZeroCommandHoldsThePositionAndTurns) {
  TrackingController controller(shippedAirframe("photographer"));
  Setpoint turn;
  turn.yaw = 1.0;
  controller.setCommand(turn, 0.0);
  controller.tick(0.0, levelAt(Vec3(4, 5, 6), 0.0));
  EXPECT_EQ(controller.memory().mode, ControlMode::YawOnly);
  EXPECT_EQ(controller.memory().reference.position, Vec3(4, 5, 6));
  EXPECT_EQ(controller.memory().reference.yaw, 1.0);
}

TEST(TrackingController, YawRateIsClamped) {
  const Airframe& airframe = shippedAirframe("explorer");
  TrackingController controller(airframe);
  controller.setCommand(positionSetpoint(Vec3(0, 0, 5), 3.0), 0.0);
  const auto out = controller.tick(0.0, levelAt(Vec3(0, 0, 5), 0.0));
  // 2.0 * 3 + 0.02 * 1.57 = 6.03 rad/s wanted, 90 deg/s allowed.
  EXPECT_DOUBLE_EQ(out->yawRate, 90.0 * kDegree);
}

TEST(TrackingController, TimeoutAfterMoreThanATenthOfASecond) {
  TrackingController controller(shippedAirframe("explorer"));
  controller.setCommand(positionSetpoint(Vec3(10, 0, 5), 0.0), 0.0);
  controller.tick(0.0, levelAt(Vec3(0, 0, 5), 0.0));
  controller.tick(0.05, levelAt(Vec3(0.1, 0, 5), 0.05));
  controller.tick(0.10, levelAt(Vec3(0.2, 0, 5), 0.10));  // exactly 0.1 s old: still tracking
  EXPECT_EQ(controller.memory().mode, ControlMode::Tracking);
  controller.tick(0.15, levelAt(Vec3(0.3, 0, 5), 0.15));
  EXPECT_EQ(controller.memory().mode, ControlMode::Holding);
  EXPECT_EQ(controller.memory().reference.position, Vec3(0.3, 0, 5));
  controller.tick(0.20, levelAt(Vec3(0.4, 0, 5), 0.20));  // the hold point is taken once
  EXPECT_EQ(controller.memory().reference.position, Vec3(0.3, 0, 5));
}

TEST(Setpoint, FinitenessCoversEveryComponent) {
  Setpoint s;
  EXPECT_TRUE(isFinite(s));
  s.velocity.y() = NAN;
  EXPECT_FALSE(isFinite(s));
  s = Setpoint{};
  s.yaw = INFINITY;
  EXPECT_FALSE(isFinite(s));
  EXPECT_NEAR(wrapAngle(3.0 * M_PI), M_PI, 1e-12);
  EXPECT_NEAR(wrapAngle(-M_PI), M_PI, 1e-12);
}

}  // namespace
}  // namespace coinspect::vehicle
