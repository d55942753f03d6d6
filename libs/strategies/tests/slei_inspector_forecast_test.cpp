// An explorer's forecast of an inspector's hover windows: every listed pose ahead of it from now
// on, or (presumeDone) the poses it would have finished by now dropped; and the approach to an
// inspector missing at a meeting point.
#include <gtest/gtest.h>

#include <cmath>

#include "coinspect/strategies/slei/inspector_forecast.h"

namespace coinspect::strategies::slei {
namespace {

// Heard of at 0 s at the origin, then given two poses 10 m apart along x; its wait point 10 m
// along y. Straight-line travel 1.5 x 5 s per 10 m, 5 s at a pose: A from 7.5 to 12.5 s, B
// from 20 to 25 s, back home at 25 + 1.5 x 14.14 / 2 = 35.6 s.
InspectorForecast twoPoses() {
  return {3, Vec3::Zero(), 0.0, {Vec3(10, 0, 0), Vec3(20, 0, 0)}, Vec3(10, 10, 0)};
}

TEST(InspectorForecast, WithoutPresumingEveryListedPoseLiesAheadFromNow) {
  // Long after: it leaves for A now.
  const auto plan = forecastInspector(twoPoses(), 100.0, {});
  ASSERT_EQ(plan.poses.size(), 3u);
  EXPECT_EQ(plan.id, 3);
  EXPECT_EQ(plan.poses[0].position, Vec3(10, 0, 0));
  EXPECT_DOUBLE_EQ(plan.poses[0].start, 107.5);
  EXPECT_DOUBLE_EQ(plan.poses[0].end, 112.5);
  EXPECT_DOUBLE_EQ(plan.poses[1].start, 120.0);
  EXPECT_EQ(plan.poses[2].position, Vec3(10, 10, 0));
  EXPECT_EQ(plan.poses[2].end, planning::kOpenWindowEnd);
}

TEST(InspectorForecast, PresumedDonePosesAreDroppedAndTheRestTimedFromItsLastStatus) {
  ForecastModel model;
  model.presumeDone = true;
  // Long after: both done, it is at its wait point from now on.
  auto plan = forecastInspector(twoPoses(), 100.0, model);
  ASSERT_EQ(plan.poses.size(), 1u);
  EXPECT_EQ(plan.poses[0].position, Vec3(10, 10, 0));
  EXPECT_DOUBLE_EQ(plan.poses[0].start, 100.0);
  // At 15 s: A done, on its way to B (there at 20 s), home after it.
  plan = forecastInspector(twoPoses(), 15.0, model);
  ASSERT_EQ(plan.poses.size(), 2u);
  EXPECT_EQ(plan.poses[0].position, Vec3(20, 0, 0));
  EXPECT_DOUBLE_EQ(plan.poses[0].start, 20.0);
  EXPECT_DOUBLE_EQ(plan.poses[0].end, 25.0);
  EXPECT_NEAR(plan.poses[1].start, 25.0 + 1.5 * std::sqrt(200.0) / 2.0, 1e-9);
  // At 10 s: still at A (until 12.5 s), which is kept, from now.
  plan = forecastInspector(twoPoses(), 10.0, model);
  ASSERT_EQ(plan.poses.size(), 3u);
  EXPECT_DOUBLE_EQ(plan.poses[0].start, 10.0);
  // At 1 s: timed from its status at 0 s (without presuming, from now: 1 s later).
  plan = forecastInspector(twoPoses(), 1.0, model);
  ASSERT_EQ(plan.poses.size(), 3u);
  EXPECT_DOUBLE_EQ(plan.poses[0].start, 7.5);
  EXPECT_DOUBLE_EQ(plan.poses[1].start, 20.0);
  EXPECT_DOUBLE_EQ(forecastInspector(twoPoses(), 1.0, {}).poses[0].start, 8.5);
}

TEST(InspectorForecast, AnApproachStopsShortOfTheExpectedPlace) {
  EXPECT_TRUE(approachPoint(Vec3(0, 0, 3), Vec3(0, 4, 3), 1.5).isApprox(Vec3(0, 2.5, 3)));
  EXPECT_EQ(approachPoint(Vec3(0, 0, 3), Vec3(0, 1, 3), 1.5), Vec3(0, 0, 3));
}

}  // namespace
}  // namespace coinspect::strategies::slei
