// 3D pictures through MRPT's CFBORender: these tests need an EGL context and fail (they do not
// skip) when none can be created, with the message saying which packages provide it.
#include "coinspect/eval/run_scene3d.h"

#include <gtest/gtest.h>
#include <mrpt/opengl/COpenGLScene.h>
#include <mrpt/opengl/CPointCloudColoured.h>
#include <mrpt/opengl/CSetOfObjects.h>
#include <mrpt/opengl/CSetOfTriangles.h>

#include "coinspect/eval/run_pictures.h"
#include "coinspect/eval/run_plots.h"
#include "coinspect/testing/input_errors.h"
#include "coinspect/testing/paths.h"
#include "picture_run.h"

namespace coinspect::eval {
namespace {

// Each test records the run in a folder of its own: ctest runs tests in parallel processes.
class RunScene3d : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto dir =
        testing::scratchDir(std::string("run_scene3d_") +
                            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    test::writePictureRun(dir / "run.rawlog");
    tracks_ = readRunTracks(dir / "run.rawlog");
  }
  RunTracks tracks_;
  world::Scenario scenario_ = test::pictureScenario();
};

int distance(Rgb a, Rgb b) {
  return std::abs(a.r - b.r) + std::abs(a.g - b.g) + std::abs(a.b - b.b);
}

// Pixels within `tolerance` (sum of channel differences) of `color` in the rectangle.
int countLike(const test::DecodedPng& png, int x0, int y0, int x1, int y1, Rgb color,
              int tolerance) {
  int count = 0;
  for (int y = y0; y < y1; ++y)
    for (int x = x0; x < x1; ++x)
      if (distance(png.at(x, y), color) <= tolerance) ++count;
  return count;
}

TEST_F(RunScene3d, WritesEveryPictureAtTheRequestedSize) {
  const auto dir = testing::scratchDir("run_scene3d_pictures");
  const auto paths = writeRunPictures(scenario_, tracks_, dir / "pictures", 320, 240);
  ASSERT_EQ(paths.size(), 5u);
  for (const auto& name : {"score.png", "top.png", "side.png", "final3d.png", "scene.3Dscene"})
    EXPECT_EQ(std::count(paths.begin(), paths.end(), dir / "pictures" / name), 1) << name;
  for (const auto& path : paths) {
    ASSERT_TRUE(std::filesystem::exists(path)) << path;
    EXPECT_GT(std::filesystem::file_size(path), 100u) << path;
    if (path.extension() == ".png") {
      EXPECT_EQ(test::pngSize(path), std::make_pair(320, 240)) << path;
    }
  }
}

TEST_F(RunScene3d, FinalRenderShowsTrajectoriesAndScoredPoints) {
  const auto dir = testing::scratchDir("run_scene3d_final");
  writeFinalScene3d(scenario_, tracks_, dir / "final3d.png", dir / "scene.3Dscene", 480, 360);
  const auto png = test::decodePng(dir / "final3d.png");
  ASSERT_EQ(png.width, 480);
  ASSERT_EQ(png.height, 360);
  // Look between the title band (top) and the legend (bottom left): only the 3D render is there.
  const int x0 = 200, y0 = 60, x1 = 480, y1 = 360;
  EXPECT_GT(countLike(png, x0, y0, x1, y1, unitColor(1), 40), 5) << "alpha's trajectory";
  EXPECT_GT(countLike(png, x0, y0, x1, y1, scoreColor(1.0), 40), 2) << "the point scored 1.0";
  // The structure: light grey, lit, in the middle of the picture.
  const Rgb middle = png.at(240, 200);
  EXPECT_LT(std::abs(middle.r - middle.g) + std::abs(middle.g - middle.b), 30);
}

TEST_F(RunScene3d, SceneFileReadsBackWithItsObjects) {
  const auto dir = testing::scratchDir("run_scene3d_file");
  writeFinalScene3d(scenario_, tracks_, dir / "final3d.png", dir / "scene.3Dscene", 160, 120);
  mrpt::opengl::COpenGLScene scene;
  ASSERT_TRUE(scene.loadFromFile((dir / "scene.3Dscene").string()));
  using namespace mrpt::opengl;
  ASSERT_TRUE(scene.getByName("structure"));
  EXPECT_EQ(
      std::dynamic_pointer_cast<CSetOfTriangles>(scene.getByName("structure"))->getTrianglesCount(),
      12u);
  auto points = std::dynamic_pointer_cast<CPointCloudColoured>(scene.getByName("interest_points"));
  ASSERT_TRUE(points);
  ASSERT_EQ(points->size(), 12u);
  const auto scored = points->getPointColor(4);
  EXPECT_EQ(Rgb({scored.R, scored.G, scored.B}), scoreColor(1.0));
  const auto unscored = points->getPointColor(1);
  EXPECT_EQ(Rgb({unscored.R, unscored.G, unscored.B}), kUnscoredColor);
  auto boxes = std::dynamic_pointer_cast<CSetOfObjects>(scene.getByName("boxes"));
  ASSERT_TRUE(boxes);
  EXPECT_EQ(boxes->size(), 1u);
  for (const auto& unit : {"gcs", "alpha", "bravo"}) {
    EXPECT_TRUE(scene.getByName(std::string("unit:") + unit)) << unit;
    EXPECT_TRUE(scene.getByName(std::string("trajectory:") + unit)) << unit;
  }
  // Trajectories are ribbons: two crossed quads (four triangles) per segment between samples.
  const auto trianglesOf = [&](const std::string& name) {
    auto group = std::dynamic_pointer_cast<CSetOfObjects>(scene.getByName(name));
    size_t count = 0;
    for (const auto& chunk : *group)
      count += std::dynamic_pointer_cast<CSetOfTriangles>(chunk)->getTrianglesCount();
    return count;
  };
  EXPECT_EQ(trianglesOf("trajectory:alpha"), 4u * 240u);
  EXPECT_EQ(trianglesOf("trajectory:gcs"), 0u);  // it never moved
  // The units stand at their final poses.
  const auto alphaMarker = scene.getByName("unit:alpha")->getPose();
  EXPECT_NEAR(alphaMarker.x, test::alphaAt(test::kEndTime).x(), 1e-6);
  EXPECT_NEAR(alphaMarker.z, 14.0, 1e-6);
}

TEST_F(RunScene3d, ReplayFramesFollowTheRun) {
  ReplayRenderer overview(scenario_, tracks_, 160, 120, CameraView{});
  const RgbImage first = overview.frameAt(0.0);
  const RgbImage last = overview.frameAt(test::kEndTime);
  ASSERT_EQ(first.width(), 160);
  ASSERT_EQ(first.height(), 120);
  int changed = 0;
  for (int y = 0; y < 120; ++y)
    for (int x = 0; x < 160; ++x)
      changed += !(first.at(x, y) == last.at(x, y));
  EXPECT_GT(changed, 100);  // trails, moved units, recoloured points, the clock

  const CameraView chase = parseCameraView("chase:alpha", tracks_, "--view");
  EXPECT_EQ(chase.mode, CameraView::Mode::Chase);
  ReplayRenderer behind(scenario_, tracks_, 160, 120, chase);
  EXPECT_EQ(behind.frameAt(3.0).width(), 160);
}

TEST_F(RunScene3d, CameraViewsAreCheckedAgainstTheRun) {
  EXPECT_EQ(parseCameraView("overview", tracks_, "--view").mode, CameraView::Mode::Overview);
  const std::string unknown =
      testing::messageOf([&] { parseCameraView("chase:zulu", tracks_, "--view"); });
  EXPECT_NE(unknown.find("zulu"), std::string::npos) << unknown;
  EXPECT_NE(unknown.find("alpha"), std::string::npos) << unknown;  // lists the units it knows
  EXPECT_NE(testing::messageOf([&] { parseCameraView("above", tracks_, "--view"); }).find("--view"),
            std::string::npos);
}

TEST(ReplayFrames, OneFramePerPeriodFromZeroToTheEnd) {
  EXPECT_EQ(replayFrameCount(12.0, 10.0), 121u);
  EXPECT_EQ(replayFrameCount(0.3, 10.0), 4u);  // 0.3 * 10 is 2.9999999999999996
  EXPECT_EQ(replayFrameCount(0.0, 25.0), 1u);
  EXPECT_EQ(replayFrameCount(1.05, 2.0), 3u);
}

}  // namespace
}  // namespace coinspect::eval
