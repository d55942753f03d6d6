#include "coinspect/eval/run_plots.h"

#include <gtest/gtest.h>

#include <cmath>

#include "coinspect/record/observations.h"
#include "coinspect/testing/paths.h"
#include "picture_run.h"
#include "pixel_count.h"

namespace coinspect::eval {
namespace {

// Each test records the run in a folder of its own: ctest runs tests in parallel processes.
class RunPlots : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto dir =
        testing::scratchDir(std::string("run_plots_") +
                            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    test::writePictureRun(dir / "run.rawlog");
    tracks_ = readRunTracks(dir / "run.rawlog");
  }
  RunTracks tracks_;
  world::Scenario scenario_ = test::pictureScenario();
};

using test::countIn;
using test::countNear;

TEST_F(RunPlots, ScorePlotDrawsScoreAboveAndDetectedBelow) {
  const RgbImage image = renderScorePlot(tracks_, "cube", 400, 300);
  ASSERT_EQ(image.width(), 400);
  ASSERT_EQ(image.height(), 300);
  const Rgb scoreLine{31, 119, 180}, detectedLine{215, 110, 20};
  EXPECT_GT(countIn(image, 0, 0, 400, 150, scoreLine), 50);
  EXPECT_EQ(countIn(image, 0, 150, 400, 300, scoreLine), 0);
  EXPECT_GT(countIn(image, 0, 150, 400, 300, detectedLine), 50);
  EXPECT_EQ(countIn(image, 0, 0, 400, 150, detectedLine), 0);
  // The dashed line and label of bravo's loss.
  EXPECT_GT(countIn(image, 0, 0, 400, 300, Rgb{190, 30, 30}), 20);
}

TEST_F(RunPlots, ScorePlotWithoutTallyStillDraws) {
  RunTracks empty;
  const RgbImage image = renderScorePlot(empty, "nothing", 200, 150);
  EXPECT_EQ(image.width(), 200);
  EXPECT_GT(countIn(image, 0, 0, 200, 150, Rgb{35, 35, 35}), 50);  // title and labels
}

TEST_F(RunPlots, TopViewShowsTrajectoriesScoredPointsAndStructure) {
  PlanFrame frame;
  const RgbImage image = renderPlanView(scenario_, tracks_, PlanAxis::Top, 480, 360, &frame);
  ASSERT_EQ(image.width(), 480);
  ASSERT_EQ(image.height(), 360);
  double x, y;
  // alpha's circle, a quarter of the way round and further on.
  for (double t : {1.5, 4.5, 7.5}) {
    frame.toPixel(test::alphaAt(t), x, y);
    EXPECT_GT(countNear(image, x, y, 1, unitColor(1)), 0) << "alpha at t = " << t;
  }
  frame.toPixel(test::bravoAt(3.0), x, y);
  EXPECT_GT(countNear(image, x, y, 1, unitColor(2)), 0);
  // Points: the roof centre scored 1.0, the roof corner 0.5, a roof edge point never scored.
  const auto& points = scenario_.interestPoints;
  frame.toPixel(points[4].position, x, y);
  EXPECT_GT(countNear(image, x, y, 1, scoreColor(1.0)), 0);
  frame.toPixel(points[0].position, x, y);
  EXPECT_GT(countNear(image, x, y, 1, scoreColor(0.5)), 0);
  frame.toPixel(points[1].position, x, y);
  EXPECT_GT(countNear(image, x, y, 1, kUnscoredColor), 0);
  // The roof, between the points: grey, darker than the far end of the shading.
  frame.toPixel(world::Vec3(1.5, -1.5, 10.0), x, y);
  const Rgb roof = image.at(static_cast<int>(x), static_cast<int>(y));
  EXPECT_EQ(roof.r, roof.g);
  EXPECT_EQ(roof.g, roof.b);
  EXPECT_LT(roof.r, 200);
  // Outside the cube and the box, nothing but background or grid.
  frame.toPixel(world::Vec3(-9.0, 9.0, 0.0), x, y);
  const Rgb outside = image.at(static_cast<int>(x), static_cast<int>(y));
  EXPECT_GE(outside.r, 236);
}

TEST_F(RunPlots, TopViewMarksMeetingsBetweenTheUnits) {
  // Without a meeting event no meeting marker; with one, a black triangle halfway between the
  // two units at that time (and a legend entry).
  const Rgb meeting{0, 0, 0};
  const RgbImage before = renderPlanView(scenario_, tracks_, PlanAxis::Top, 480, 360);
  EXPECT_EQ(countIn(before, 0, 0, 480, 360, meeting), 0);
  RunEvent event;
  event.time = 4.5;
  event.kind = record::MissionEventKind::Meeting;
  event.unit = tracks_.units[1].name;
  event.detail = tracks_.units[2].name;
  tracks_.events.push_back(event);
  PlanFrame frame;
  const RgbImage image = renderPlanView(scenario_, tracks_, PlanAxis::Top, 480, 360, &frame);
  double x, y;
  frame.toPixel(0.5 * (test::alphaAt(4.5) + test::bravoAt(4.5)), x, y);
  EXPECT_GT(countNear(image, x, y, 3, meeting), 5);
  // The legend's marker, right of the plot.
  EXPECT_GT(countIn(image, frame.right + 1, 0, 480, 360, meeting), 5);
}

TEST_F(RunPlots, SideViewShowsTheLossAndTheNearestPoints) {
  PlanFrame frame;
  const RgbImage image = renderPlanView(scenario_, tracks_, PlanAxis::Side, 480, 360, &frame);
  ASSERT_EQ(image.width(), 480);
  double x, y;
  frame.toPixel(test::bravoAt(2.0), x, y);
  EXPECT_GT(countNear(image, x, y, 1, unitColor(2)), 0);
  // bravo was lost at t = 8 where it lies on the ground: a dark cross there.
  frame.toPixel(test::bravoAt(test::kBravoLost), x, y);
  EXPECT_GT(countNear(image, x, y, 3, Rgb{20, 20, 20}), 3);
  // Points 0, 1, 2 share x and z; point 0 (y = -3) is nearest the viewer at -y and drawn last.
  frame.toPixel(scenario_.interestPoints[0].position, x, y);
  EXPECT_GT(countNear(image, x, y, 1, scoreColor(0.5)), 0);
  // z grows upward: the roof is above the ground line.
  double xr, yr, xg, yg;
  frame.toPixel(world::Vec3(0, 0, 10), xr, yr);
  frame.toPixel(world::Vec3(0, 0, 0), xg, yg);
  EXPECT_LT(yr, yg);
}

TEST_F(RunPlots, UnitColoursAreDistinctAndOffTheScoreRamp) {
  for (size_t i = 0; i < 10; ++i) {
    for (size_t j = 0; j < i; ++j)
      EXPECT_FALSE(unitColor(i) == unitColor(j)) << i << " " << j;
    for (int k = 0; k <= 100; ++k)
      EXPECT_FALSE(unitColor(i) == scoreColor(k / 100.0));
    EXPECT_FALSE(unitColor(i) == kUnscoredColor);
  }
}

}  // namespace
}  // namespace coinspect::eval
