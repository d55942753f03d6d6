#include "coinspect/planning/trajectory.h"

#include <gtest/gtest.h>

#include <cmath>

#include "coinspect/core/random.h"

namespace coinspect::planning {
namespace {

double distanceToPolyline(const Vec3& p, const std::vector<Vec3>& polyline) {
  double best = (p - polyline.front()).norm();
  for (size_t i = 1; i < polyline.size(); ++i) {
    const Vec3 a = polyline[i - 1], d = polyline[i] - a;
    const double s = std::clamp((p - a).dot(d) / d.squaredNorm(), 0.0, 1.0);
    best = std::min(best, (a + s * d - p).norm());
  }
  return best;
}

// Finite differences of sampled positions never exceed the speed and acceleration limits, the
// sampled velocity is the derivative of the position, the flight stays within the corner
// tolerance of the polyline and ends at rest on the last vertex.
void checkLimits(const std::vector<Vec3>& polyline, const TrajectoryLimits& limits,
                 double minTopSpeed = 0.0) {
  const Trajectory trajectory(polyline, limits);
  const double h = 1e-3;
  const double duration = trajectory.duration();
  ASSERT_GT(duration, 0.0);
  double topSpeed = 0.0;
  for (double t = h; t + h <= duration; t += h) {
    const Vec3 p0 = trajectory.sample(t - h).position;
    const Vec3 p1 = trajectory.sample(t).position;
    const Vec3 p2 = trajectory.sample(t + h).position;
    const double speed = (p2 - p1).norm() / h;
    topSpeed = std::max(topSpeed, speed);
    ASSERT_LE(speed, limits.maxSpeed * (1.0 + 1e-6)) << "t " << t;
    ASSERT_LE((p2 - 2.0 * p1 + p0).norm() / (h * h), limits.maxAcceleration * (1.0 + 1e-4))
        << "t " << t;
    const TrajectorySample sample = trajectory.sample(t);
    ASSERT_LE((sample.velocity - (p2 - p0) / (2.0 * h)).norm(), limits.maxAcceleration * h);
    ASSERT_LE(sample.velocity.norm(), limits.maxSpeed * (1.0 + 1e-9));
    ASSERT_LE(sample.acceleration.norm(), limits.maxAcceleration * (1.0 + 1e-9));
    ASSERT_LE(distanceToPolyline(sample.position, polyline), limits.cornerTolerance + 1e-9);
  }
  EXPECT_GE(topSpeed, minTopSpeed);  // it does fly, not crawl
  const TrajectorySample end = trajectory.sample(duration);
  EXPECT_LT((end.position - polyline.back()).norm(), 1e-9);
  EXPECT_LT((trajectory.sample(duration - 1e-9).position - polyline.back()).norm(), 1e-6);
  EXPECT_NEAR(end.velocity.norm(), limits.endSpeed, 1e-9);
  EXPECT_LT((trajectory.sample(0.0).position - polyline.front()).norm(), 1e-12);
}

TEST(Trajectory, RespectsLimitsOnRandomPolylines) {
  for (uint64_t seed = 1; seed <= 6; ++seed) {
    Rng rng(seed);
    std::vector<Vec3> polyline{Vec3::Zero()};
    for (int i = 0; i < 8; ++i)
      polyline.push_back(polyline.back() +
                         Vec3(rng.uniform(-6, 6), rng.uniform(-6, 6), rng.uniform(-2, 2)));
    TrajectoryLimits limits;
    limits.maxSpeed = rng.uniform(1.0, 4.0);
    limits.maxAcceleration = rng.uniform(0.5, 3.0);
    limits.cornerTolerance = rng.uniform(0.05, 0.5);
    checkLimits(polyline, limits, 0.5 * limits.maxSpeed);
  }
}

TEST(Trajectory, SharpTurnsReversalsAndDuplicates) {
  TrajectoryLimits limits;
  limits.maxSpeed = 3.0;
  checkLimits({Vec3(0, 0, 0), Vec3(10, 0, 0), Vec3(0, 0.1, 0), Vec3(0, 0.1, 0), Vec3(0, 5, 0)},
              limits);
  checkLimits({Vec3(0, 0, 0), Vec3(0.3, 0, 0), Vec3(0.3, 0.3, 0), Vec3(0.6, 0.3, 0.3)}, limits);
}

// Slower corners for sharper turns: a right angle is taken slower than a 20 degree bend.
TEST(Trajectory, CornerSpeedFallsWithTheTurnAngle) {
  TrajectoryLimits limits;
  limits.maxSpeed = 5.0;
  limits.maxAcceleration = 2.0;
  const auto cornerSpeed = [&](double angle) {
    const Vec3 corner(20, 0, 0);
    const Trajectory trajectory(
        {Vec3::Zero(), corner, corner + 20.0 * Vec3(std::cos(angle), std::sin(angle), 0)}, limits);
    double slowest = 1e9;  // the speed nearest the corner
    double nearest = 1e9;
    for (double t = 0.0; t < trajectory.duration(); t += 1e-3) {
      const TrajectorySample s = trajectory.sample(t);
      if ((s.position - corner).norm() < nearest) {
        nearest = (s.position - corner).norm();
        slowest = s.velocity.norm();
      }
    }
    return slowest;
  };
  const double gentle = cornerSpeed(20.0 * M_PI / 180.0);
  const double square = cornerSpeed(M_PI / 2.0);
  EXPECT_GT(gentle, square + 0.5);
  // v = sqrt(2 a tol) / sin(theta / 2) at the corner (the speed dips by cos(theta / 2) at the
  // blend's apex).
  EXPECT_NEAR(square, std::sqrt(2.0 * 2.0 * 0.2) / std::sin(M_PI / 4.0) * std::cos(M_PI / 4.0),
              0.01);
}

TEST(Trajectory, StartAndEndSpeedsAndSegmentLimits) {
  TrajectoryLimits limits;
  limits.maxSpeed = 4.0;
  limits.maxAcceleration = 1.0;
  limits.startSpeed = 2.0;
  limits.endSpeed = 1.0;
  limits.segmentSpeeds = {4.0, 1.5, 4.0};
  const std::vector<Vec3> polyline{Vec3(0, 0, 0), Vec3(30, 0, 0), Vec3(30, 20, 0), Vec3(60, 20, 0)};
  const Trajectory trajectory(polyline, limits);
  EXPECT_NEAR(trajectory.sample(0.0).velocity.x(), 2.0, 1e-12);
  EXPECT_NEAR(trajectory.startSpeed(), 2.0, 1e-12);
  EXPECT_NEAR(trajectory.sample(trajectory.duration()).velocity.x(), 1.0, 1e-12);
  for (double t = 0.0; t < trajectory.duration(); t += 0.01) {
    const TrajectorySample s = trajectory.sample(t);
    const bool onSlowSegment =
        std::abs(s.position.x() - 30.0) < 1e-6 && s.position.y() > 1.0 && s.position.y() < 19.0;
    if (onSlowSegment) {
      EXPECT_LE(s.velocity.norm(), 1.5 + 1e-9);
    }
  }
  checkLimits(polyline, limits);
  // Too short to brake from the start speed: the start speed is lowered, not the limits broken.
  TrajectoryLimits tight;
  tight.startSpeed = 2.0;
  const Trajectory shortOne({Vec3::Zero(), Vec3(0.5, 0, 0)}, tight);
  EXPECT_NEAR(shortOne.startSpeed(), 1.0, 1e-12);  // sqrt(2 a L)
}

TEST(Trajectory, DegenerateInputs) {
  const Trajectory single({Vec3(1, 2, 3)}, TrajectoryLimits{});
  EXPECT_EQ(single.duration(), 0.0);
  EXPECT_EQ(single.sample(1.0).position, Vec3(1, 2, 3));
  const Trajectory none({}, TrajectoryLimits{});
  EXPECT_EQ(none.sample(0.0).position, Vec3::Zero());
}

}  // namespace
}  // namespace coinspect::planning
