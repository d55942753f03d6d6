#include "coinspect/vehicle/multirotor.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>

#include "flight.h"

namespace coinspect::vehicle {
namespace {

using testing::fly;
using testing::kDegree;
using testing::kPhysicsStep;
using testing::shippedAirframe;

constexpr double kG = 9.81;

// Overshoot the integral term can cause after a saturated step: the sum (one error per tick)
// saturates at the clamp during the approach and only unwinds once the error changes sign, so the
// loop settles first around the offset where w^2 e balances ki * clamp. A critically damped (or
// overdamped) linear loop adds no overshoot of its own; 1 cm covers the attitude lag (time
// constant 0.1 s) and the 20 Hz sample-and-hold.
double integralOvershoot(const Airframe& a, double w, double ki) {
  return ki * a.integralClamp / (w * w);
}
constexpr double kLagMargin = 0.01;

TEST(Multirotor, StaysOnTheGroundBeforeTheFirstCommand) {
  Multirotor vehicle(shippedAirframe("explorer"), Vec3(1, 2, 0.1), 0.5);
  vehicle.advance(2.0);
  EXPECT_EQ(vehicle.state().position, Vec3(1, 2, 0.1));
  EXPECT_NEAR(vehicle.state().yaw, 0.5, 1e-15);
  EXPECT_FALSE(vehicle.airborne());
  EXPECT_TRUE(vehicle.alive());
  EXPECT_DOUBLE_EQ(vehicle.state().time, 2.0);
}

TEST(Multirotor, HoverStaysPut) {
  // At the reference with zero velocity the command is exactly (0, 0, g): thrust m g, level, so
  // the vehicle must not move at all (up to rounding).
  const Vec3 start(1, 2, 5);
  Multirotor vehicle(shippedAirframe("photographer"), start, 0.3);
  double maxDeviation = 0.0;
  fly(vehicle, positionSetpoint(start, 0.3), 10.0, [&](const Multirotor& v) {
    maxDeviation = std::max(maxDeviation, (v.state().position - start).norm());
  });
  EXPECT_LT(maxDeviation, 1e-6);
  EXPECT_TRUE(vehicle.airborne());
}

TEST(Multirotor, PositionStepSettlesWithBoundedOvershoot) {
  for (const char* name : {"explorer", "photographer"}) {
    const Airframe& airframe = shippedAirframe(name);
    Multirotor vehicle(airframe, Vec3(0, 0, 10), 0.0);
    double maxX = 0.0;
    fly(vehicle, positionSetpoint(Vec3(5, 0, 10), 0.0), 12.0,
        [&](const Multirotor& v) { maxX = std::max(maxX, v.state().position.x()); });
    const double bound = integralOvershoot(airframe, airframe.gains.wXY, airframe.gains.kiXY);
    EXPECT_LE(maxX - 5.0, bound + kLagMargin) << name;
    // From 12 s on it stays within 5 cm (the offset left by the integral is below it and shrinks).
    fly(vehicle, positionSetpoint(Vec3(5, 0, 10), 0.0), 3.0, [&](const Multirotor& v) {
      EXPECT_LT((v.state().position - Vec3(5, 0, 10)).norm(), 0.05) << name;
    });
  }
}

TEST(Multirotor, AltitudeStepSettles) {
  // 0.5 m up: 16 * 0.5 + g stays below the 2 g clamp, zeta_z = 1.1 is overdamped.
  const Airframe& airframe = shippedAirframe("explorer");
  Multirotor vehicle(airframe, Vec3(0, 0, 10), 0.0);
  double maxZ = 0.0;
  fly(vehicle, positionSetpoint(Vec3(0, 0, 10.5), 0.0), 3.0,
      [&](const Multirotor& v) { maxZ = std::max(maxZ, v.state().position.z()); });
  EXPECT_LE(maxZ - 10.5,
            integralOvershoot(airframe, airframe.gains.wZ, airframe.gains.kiZ) + kLagMargin);
  EXPECT_NEAR(vehicle.state().position.z(), 10.5, 0.05);
}

TEST(Multirotor, TracksAVelocityCommand) {
  // Steady state of velocity control (position zero): damping 2 zeta w (v_ref - v) balances the
  // drag c v / m and the reference's integral of (0 - p), saturated at -clamp once x > 0.5 m:
  //   x: 2 zeta w (2 - v) - ki clamp - c v / m = 0,
  //   z: 2 zeta_z w_z (0 - v) - ki_z clamp - c v / m = 0 (a slow sink: the reference's quirk).
  const Airframe& a = shippedAirframe("explorer");
  Multirotor vehicle(a, Vec3(0, 0, 20), 0.0);
  fly(vehicle, velocitySetpoint(Vec3(2, 0, 0), 0.0), 10.0);
  const double dampX = 2.0 * a.gains.zetaXY * a.gains.wXY;
  const double dampZ = 2.0 * a.gains.zetaZ * a.gains.wZ;
  const double drag = a.dragCoefficient / a.mass;
  const double expectedX = (dampX * 2.0 - a.gains.kiXY * a.integralClamp) / (dampX + drag);
  const double expectedZ = -a.gains.kiZ * a.integralClamp / (dampZ + drag);
  EXPECT_NEAR(vehicle.state().velocity.x(), expectedX, 0.005);
  EXPECT_NEAR(vehicle.state().velocity.y(), 0.0, 1e-9);
  EXPECT_NEAR(vehicle.state().velocity.z(), expectedZ, 0.005);
}

TEST(Multirotor, TiltNeverExceedsItsLimit) {
  for (const char* name : {"explorer", "photographer"}) {
    const Airframe& a = shippedAirframe(name);
    Multirotor vehicle(a, Vec3(0, 0, 10), 0.0);
    double maxAngle = 0.0;
    const auto check = [&](const Multirotor& v) {
      maxAngle = std::max({maxAngle, std::abs(v.state().roll), std::abs(v.state().pitch)});
    };
    fly(vehicle, positionSetpoint(Vec3(40, -40, 20), 0.0), 6.0, check);  // every 2.5 ms
    fly(vehicle, positionSetpoint(Vec3(-40, 40, 5), 0.0), 6.0, check);
    EXPECT_LE(maxAngle, a.tiltLimit) << name;
    // It did reach the limit: the steps are aggressive enough to test it.
    EXPECT_GT(maxAngle, a.tiltLimit - 5.0 * kDegree) << name;
  }
}

TEST(Multirotor, YawRateIsLimitedTo90DegreesPerSecond) {
  const Airframe& a = shippedAirframe("photographer");
  Multirotor vehicle(a, Vec3(0, 0, 10), 0.0);
  double maxRate = 0.0;
  fly(vehicle, positionSetpoint(Vec3(0, 0, 10), 3.0), 1.8, [&](const Multirotor& v) {
    maxRate = std::max(maxRate, std::abs(v.state().angularVelocity.z()));
  });
  EXPECT_LE(maxRate, a.yawRateLimit + 1e-9);
  // 3 rad at 90 deg/s takes at least 1.91 s: after 1.8 s it cannot be there yet.
  EXPECT_LT(vehicle.state().yaw, 3.0 - 0.05);
  fly(vehicle, positionSetpoint(Vec3(0, 0, 10), 3.0), 4.0);
  EXPECT_NEAR(vehicle.state().yaw, 3.0, 1.0 * kDegree);
}

TEST(Multirotor, CommandTimeoutHoldsWhereItHappened) {
  const Airframe& a = shippedAirframe("explorer");
  Multirotor vehicle(a, Vec3(0, 0, 10), 0.0);
  fly(vehicle, positionSetpoint(Vec3(30, 0, 10), 0.0), 2.0);
  // fly() sends at the ticks; the last command was at 1.95 s. At 2.05 s it is 0.1 s old (still
  // valid), at 2.10 s it is too old: that tick takes the hold point.
  Vec3 positionAtTimeout = Vec3::Zero();
  for (int i = 0; i < 40; ++i) {
    vehicle.advance(kPhysicsStep);
    const ControlMode mode = vehicle.snapshot().controller.mode;
    if (std::abs(vehicle.state().time - 2.05) < 1e-9) {
      EXPECT_EQ(mode, ControlMode::Tracking);
    }
    if (std::abs(vehicle.state().time - 2.10) < 1e-9) {
      EXPECT_EQ(mode, ControlMode::Holding);
      positionAtTimeout = vehicle.state().position;
    }
  }
  const Setpoint hold = vehicle.snapshot().controller.reference;
  EXPECT_EQ(hold.position, positionAtTimeout);
  EXPECT_EQ(hold.velocity, Vec3::Zero());
  vehicle.advance(10.0);
  // The integral was saturated forward during the approach: it settles at most ki clamp / w^2
  // past the hold point, and is at rest.
  const double bound = integralOvershoot(a, a.gains.wXY, a.gains.kiXY) + kLagMargin;
  EXPECT_LT((vehicle.state().position - positionAtTimeout).norm(), bound);
  EXPECT_LT(vehicle.state().velocity.norm(), 0.02);
}

TEST(Multirotor, NonFiniteCommandsAreRejectedAndCounted) {
  const Vec3 start(0, 0, 8);
  Multirotor vehicle(shippedAirframe("photographer"), start, 0.0);
  Setpoint nanPosition = positionSetpoint(start, 0.0);
  nanPosition.position.x() = NAN;
  Setpoint infVelocity = positionSetpoint(start, 0.0);
  infVelocity.velocity.z() = -INFINITY;
  Setpoint nanYaw = positionSetpoint(start, NAN);
  EXPECT_TRUE(vehicle.command(positionSetpoint(start, 0.0), 0.0));
  for (int i = 0; i < 40; ++i) {
    EXPECT_FALSE(vehicle.command(nanPosition, vehicle.state().time));
    EXPECT_FALSE(vehicle.command(infVelocity, vehicle.state().time));
    EXPECT_FALSE(vehicle.command(nanYaw, vehicle.state().time));
    vehicle.advance(0.05);
  }
  EXPECT_EQ(vehicle.rejectedCommands(), 120);
  const VehicleState& s = vehicle.state();
  EXPECT_TRUE(s.position.allFinite() && s.velocity.allFinite() && s.angularVelocity.allFinite());
  EXPECT_TRUE(std::isfinite(s.roll) && std::isfinite(s.pitch) && std::isfinite(s.yaw));
  // Only the valid command counted: it timed out and the vehicle held where it was.
  EXPECT_LT((s.position - start).norm(), 1e-6);
}

TEST(Multirotor, KilledVehicleFallsBallisticallyAndRests) {
  Multirotor vehicle(shippedAirframe("explorer"), Vec3(3, 4, 20), 0.0);
  fly(vehicle, positionSetpoint(Vec3(3, 4, 20), 0.0), 1.0);
  const Vec3 p0 = vehicle.state().position;
  vehicle.kill();
  EXPECT_FALSE(vehicle.alive());
  EXPECT_TRUE(vehicle.airborne());
  vehicle.advance(1.0);  // z = z0 - g / 2 (from rest)
  EXPECT_NEAR(vehicle.state().position.z(), p0.z() - 0.5 * kG, 1e-6);
  EXPECT_NEAR(vehicle.state().velocity.z(), -kG, 1e-6);
  EXPECT_TRUE(vehicle.airborne());
  vehicle.command(positionSetpoint(Vec3(3, 4, 20), 0.0), vehicle.state().time);  // ignored
  vehicle.advance(2.0);  // it hits the ground after sqrt(2 * 20 / g) = 2.02 s
  EXPECT_DOUBLE_EQ(vehicle.state().position.z(), 0.0);
  EXPECT_EQ(vehicle.state().velocity, Vec3::Zero());
  EXPECT_NEAR(vehicle.state().position.x(), 3.0, 1e-6);
  EXPECT_FALSE(vehicle.airborne());
  EXPECT_FALSE(vehicle.alive());
}

TEST(Multirotor, KilledWhileMovingLandsWhereProjectileMotionSays) {
  Multirotor vehicle(shippedAirframe("photographer"), Vec3(0, 0, 10), 0.0, -2.0);
  fly(vehicle, velocitySetpoint(Vec3(3, 0, 1), 0.0), 3.0);
  const Vec3 p0 = vehicle.state().position;
  const Vec3 v0 = vehicle.state().velocity;
  vehicle.kill();
  vehicle.advance(5.0);
  // z0 + vz t - g t^2 / 2 = groundZ at t = (vz + sqrt(vz^2 + 2 g (z0 - groundZ))) / g.
  const double t = (v0.z() + std::sqrt(v0.z() * v0.z() + 2.0 * kG * (p0.z() + 2.0))) / kG;
  EXPECT_NEAR(vehicle.state().position.x(), p0.x() + v0.x() * t, 1e-9);
  EXPECT_DOUBLE_EQ(vehicle.state().position.z(), -2.0);
}

TEST(Multirotor, LandsOnTheGroundWithoutDying) {
  Multirotor vehicle(shippedAirframe("explorer"), Vec3(0, 0, 2), 0.0, 0.5);
  fly(vehicle, positionSetpoint(Vec3(0, 0, -1), 0.0), 5.0);
  EXPECT_DOUBLE_EQ(vehicle.state().position.z(), 0.5);
  EXPECT_EQ(vehicle.state().velocity, Vec3::Zero());
  EXPECT_FALSE(vehicle.airborne());
  EXPECT_TRUE(vehicle.alive());
  fly(vehicle, positionSetpoint(Vec3(0, 0, 3), 0.0), 4.0);  // and takes off again
  EXPECT_TRUE(vehicle.airborne());
  EXPECT_NEAR(vehicle.state().position.z(), 3.0, 0.1);
}

TEST(Multirotor, ControllerRunsOnTheTickGridWhateverTheStep) {
  Multirotor vehicle(shippedAirframe("explorer"), Vec3(0, 0, 10), 0.0);
  vehicle.command(positionSetpoint(Vec3(5, 3, 12), 1.0), 0.0);
  double lastThrust = -1.0;
  for (int i = 0; i < 200; ++i) {
    if (i % 10 == 0) vehicle.command(positionSetpoint(Vec3(5, 3, 12), 1.0), vehicle.state().time);
    vehicle.advance(0.007);
    // With a 7 ms step the input only changes when a step crossed a multiple of 0.05 s.
    const double thrust = vehicle.attitudeCommand().thrust;
    if (thrust != lastThrust) {
      const double ticks = vehicle.state().time / kControlPeriod;
      const double crossed = std::floor(ticks + 1e-9) * kControlPeriod;
      EXPECT_GT(crossed, vehicle.state().time - 0.007 - 1e-9);
    }
    lastThrust = thrust;
  }
}

std::vector<double> flyPattern(Multirotor& vehicle, double seconds) {
  const Vec3 waypoints[] = {{10, 0, 10}, {10, 10, 15}, {0, 10, 5}, {0, 0, 10}};
  std::vector<double> trace;
  const int steps = static_cast<int>(seconds / kPhysicsStep + 0.5);
  for (int i = 0; i < steps; ++i) {
    const Vec3& target = waypoints[(i / 1200) % 4];
    if (i % 20 == 0)
      vehicle.command(positionSetpoint(target, 0.5 * (i / 1200)), vehicle.state().time);
    vehicle.advance(kPhysicsStep);
    const VehicleState& s = vehicle.state();
    trace.insert(trace.end(), {s.position.x(), s.position.y(), s.position.z(), s.yaw, s.roll});
  }
  return trace;
}

bool bitIdentical(const std::vector<double>& a, const std::vector<double>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0;
}

TEST(Multirotor, TwoRunsAreBitIdentical) {
  Multirotor first(shippedAirframe("explorer"), Vec3(0, 0, 0.1), 0.0);
  Multirotor second(shippedAirframe("explorer"), Vec3(0, 0, 0.1), 0.0);
  EXPECT_TRUE(bitIdentical(flyPattern(first, 15.0), flyPattern(second, 15.0)));
}

TEST(Multirotor, RestoredSnapshotContinuesBitIdentically) {
  Multirotor original(shippedAirframe("photographer"), Vec3(0, 0, 0.1), 0.0);
  flyPattern(original, 3.0125);  // mid-way between two control ticks
  const MultirotorSnapshot saved = original.snapshot();
  Multirotor copy(shippedAirframe("photographer"), Vec3(7, 7, 7), 1.0);
  copy.restore(saved);
  EXPECT_TRUE(bitIdentical(flyPattern(original, 6.0), flyPattern(copy, 6.0)));
}

TEST(Multirotor, RungeKuttaReferenceAgreesWithCvode) {
  IntegratorOptions rk4;
  rk4.method = Integrator::Rk4;
  Multirotor cvode(shippedAirframe("explorer"), Vec3(0, 0, 0.1), 0.0);
  Multirotor reference(shippedAirframe("explorer"), Vec3(0, 0, 0.1), 0.0, 0.0, rk4);
  flyPattern(cvode, 10.0);
  flyPattern(reference, 10.0);
  EXPECT_LT((cvode.state().position - reference.state().position).norm(), 1e-3);
}

}  // namespace
}  // namespace coinspect::vehicle
