#include "coinspect/eval/feature_plot.h"

#include <gtest/gtest.h>

#include <cmath>

#include "coinspect/eval/run_plots.h"
#include "pixel_count.h"

namespace coinspect::eval {
namespace {

constexpr Rgb kTotalLine{120, 120, 120};
constexpr Rgb kText{35, 35, 35};

using test::countIn;
using test::countNear;

FeatureCurve curve(const std::string& label, std::vector<double> times, double budget = 100.0) {
  return {label, "slei-a", std::move(times), 5, budget};
}

TEST(FeaturePlot, EachCurveStepsUpAtItsTimesInItsOwnColour) {
  // Times out of order and two at once: the count is 1 from 10 s, 2 from 20 s, 4 from 30 s.
  const std::vector<FeatureCurve> curves = {curve("fast", {30.0, 10.0, 20.0, 30.0}),
                                            curve("idle", {})};
  FeaturePlotFrame frame;
  const RgbImage image = renderFeaturePlot("collected", curves, 400, 300, &frame);
  ASSERT_EQ(image.width(), 400);
  ASSERT_EQ(image.height(), 300);
  EXPECT_DOUBLE_EQ(frame.timeLo, 0.0);
  EXPECT_DOUBLE_EQ(frame.timeHi, 100.0);
  EXPECT_GE(frame.countHi, 5.0);
  const Rgb fast = unitColor(0), idle = unitColor(1);
  ASSERT_FALSE(fast == idle);
  EXPECT_GT(countNear(image, frame.x(15.0), frame.y(1.0), 1, fast), 0);
  EXPECT_GT(countNear(image, frame.x(25.0), frame.y(2.0), 1, fast), 0);
  EXPECT_GT(countNear(image, frame.x(60.0), frame.y(4.0), 1, fast), 0);
  EXPECT_GT(countNear(image, frame.x(20.0), frame.y(1.5), 1, fast), 0);  // the riser at 20 s
  // Steps, not a ramp: nothing between the levels away from the risers, no third level.
  EXPECT_EQ(countNear(image, frame.x(15.0), frame.y(1.5), 2, fast), 0);
  EXPECT_EQ(countNear(image, frame.x(60.0), frame.y(3.0), 2, fast), 0);
  // The curve with no event stays at 0 up to the budget, drawn over the first one there.
  EXPECT_GT(countNear(image, frame.x(5.0), frame.y(0.0), 1, idle), 0);
  EXPECT_GT(countNear(image, frame.x(95.0), frame.y(0.0), 1, idle), 0);
  // The dashed line at the 5 features of the scenario, across the plot.
  const int totalRow = static_cast<int>(std::lround(frame.y(5.0)));
  EXPECT_GT(countIn(image, frame.left, totalRow, frame.right, totalRow + 1, kTotalLine),
            (frame.right - frame.left) / 3);
}

TEST(FeaturePlot, LegendRightOfThePlotShowsEachRunsColour) {
  FeaturePlotFrame frame;
  const RgbImage image = renderFeaturePlot(
      "inspected", {curve("slei3d", {10.0}), curve("caric-team", {50.0})}, 600, 400, &frame);
  EXPECT_GE(frame.legendLeft, frame.right);
  EXPECT_LE(frame.legendRight, image.width());
  EXPECT_GT(frame.legendBottom, frame.legendTop);
  const auto inLegend = [&](Rgb color) {
    return countIn(image, frame.legendLeft, frame.legendTop, frame.legendRight, frame.legendBottom,
                   color);
  };
  EXPECT_GT(inLegend(unitColor(0)), 5);
  EXPECT_GT(inLegend(unitColor(1)), 5);
  EXPECT_GT(inLegend(kText), 50);  // the labels
}

TEST(FeaturePlot, EachCurveStopsAtItsOwnBudgetAndTheAxisReachesTheLatestEvent) {
  FeaturePlotFrame frame;
  // The first run's last feature came after its budget (the clock runs a little past it).
  const RgbImage image = renderFeaturePlot(
      "collected", {curve("long", {130.0}, 120.0), curve("short", {10.0}, 50.0)}, 400, 300, &frame);
  EXPECT_GE(frame.timeHi, 130.0);
  EXPECT_GT(countNear(image, frame.x(130.0), frame.y(0.5), 1, unitColor(0)), 0);
  EXPECT_GT(countNear(image, frame.x(40.0), frame.y(1.0), 1, unitColor(1)), 0);
  EXPECT_EQ(countNear(image, frame.x(80.0), frame.y(1.0), 2, unitColor(1)), 0);
}

TEST(FeaturePlot, NoCurvesDrawsTheAxesAndNoLegend) {
  FeaturePlotFrame frame;
  const RgbImage image = renderFeaturePlot("discovered", {}, 200, 150, &frame);
  EXPECT_EQ(image.width(), 200);
  EXPECT_EQ(frame.legendRight, frame.legendLeft);
  EXPECT_GT(frame.right, frame.left);
  EXPECT_GT(countIn(image, 0, 0, 200, 150, kText), 50);  // title and tick labels
  EXPECT_EQ(countIn(image, 0, 0, 200, 150, unitColor(0)), 0);
}

TEST(FeaturePlot, TitleNamesStageScenariosAndTotals) {
  EXPECT_EQ(featurePlotTitle("collected", {curve("a", {}), curve("b", {})}),
            "features collected over time (slei-a, 5 features)");
  FeatureCurve other{"c", "slei-b", {}, 150, 600.0};
  EXPECT_EQ(featurePlotTitle("assigned", {curve("a", {}), other}),
            "features assigned over time (slei-a, slei-b, 5/150 features)");
  other.scenario.clear();
  EXPECT_EQ(featurePlotTitle("assigned", {other}), "features assigned over time (150 features)");
  EXPECT_EQ(featurePlotTitle("inspected", {}), "features inspected over time (no runs)");
}

}  // namespace
}  // namespace coinspect::eval
