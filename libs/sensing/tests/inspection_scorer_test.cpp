// The scoring formulas on hand-built scenes. Every expected number is derived in the comments:
// k = c / f * 1000 = 0.271875 mm/px per metre, f tau / c = 3.678 px per (m/s / m).
#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "coinspect/core/error.h"
#include "coinspect/sensing/inspection_scorer.h"
#include "sensing_scenes.h"

namespace coinspect::sensing {
namespace {

using test::cameraAt;
using test::facingMinusX;
using test::wallX;

constexpr double kDeg = M_PI / 180.0;

// A 40 m x 20 m wall at x = 10 facing the origin, optionally a 2 m x 2 m panel at x = 5 around
// (5, 0, 5), and interest points given by each test.
class ScorerTest : public ::testing::Test {
 protected:
  void build(std::vector<world::InterestPoint> points, bool withPanel = false,
             ScoringMode mode = ScoringMode::Caric) {
    std::vector<world::TriangleMesh> meshes{wallX(10.0, -20.0, 20.0, -5.0, 15.0)};
    if (withPanel) meshes.push_back(wallX(5.0, -1.0, 1.0, 4.0, 6.0));
    points_ = world::InterestPointSet(std::move(points));
    caster_ = std::make_unique<world::RayCaster>(meshes, std::nullopt);
    scorer_ = std::make_unique<InspectionScorer>(points_, *caster_, mode);
  }
  PointScore one(const CaptureState& state, uint32_t index = 0, const Occluders& occ = {}) {
    return scorer_->scorePoint(spec_, state, occ, index);
  }

  CameraSpec spec_;  // MBS camera: r_des 2 mm/px
  world::InterestPointSet points_;
  std::unique_ptr<world::RayCaster> caster_;
  std::unique_ptr<InspectionScorer> scorer_;
};

TEST_F(ScorerTest, FrontalAtNominalDistanceHasFullResolution) {
  build({facingMinusX(10, 0, 5)});
  // 0.271875 * 7.356 = 1.99991 mm/px -> q_res = min(2 / 1.99991, 1) = 1.
  const PointScore ps = one(cameraAt(spec_, Vec3(10 - 7.356, 0, 5)));
  EXPECT_TRUE(ps.seen) << toString(ps.reason);
  EXPECT_NEAR(ps.mmPerPixel, 0.271875 * 7.356, 1e-6);
  EXPECT_NEAR(ps.qRes, 1.0, 1e-3);
  EXPECT_NEAR(ps.qBlur, 1.0, 1e-12);
  EXPECT_NEAR(ps.score, 1.0, 1e-3);
  EXPECT_TRUE(ps.counted);
}

TEST_F(ScorerTest, FrontalAtTwiceNominalDistanceHasHalfResolution) {
  build({facingMinusX(10, 0, 5)});
  // 0.271875 * 14.712 = 3.99983 mm/px -> q_res = 2 / 3.99983 = 0.50002.
  const PointScore ps = one(cameraAt(spec_, Vec3(10 - 14.712, 0, 5)));
  EXPECT_TRUE(ps.seen) << toString(ps.reason);
  EXPECT_NEAR(ps.qRes, 0.5, 1e-3);
  EXPECT_NEAR(ps.score, 0.5, 1e-3);
}

TEST_F(ScorerTest, HorizontalFovEdgeIsInclusive) {
  const double y = 10.0 * std::tan(40 * kDeg);  // atan(y/x) = HFOV/2 exactly
  const double beyond = 10.0 * std::tan(40.01 * kDeg);
  build({facingMinusX(10, y, 5), facingMinusX(10, -y, 5), facingMinusX(10, beyond, 5)});
  const CaptureState state = cameraAt(spec_, Vec3(0, 0, 5));
  EXPECT_TRUE(one(state, 0).seen) << toString(one(state, 0).reason);
  EXPECT_TRUE(one(state, 1).seen) << toString(one(state, 1).reason);
  EXPECT_EQ(one(state, 2).reason, NotSeenReason::OutsideHorizontalFov);
  EXPECT_FALSE(one(state, 2).seen);
}

TEST_F(ScorerTest, VerticalFovEdgeIsInclusive) {
  const double z = 10.0 * std::tan(30 * kDeg);
  const double beyond = 10.0 * std::tan(30.01 * kDeg);
  build({facingMinusX(10, 0, 5 + z), facingMinusX(10, 0, 5 - z), facingMinusX(10, 0, 5 - beyond)});
  const CaptureState state = cameraAt(spec_, Vec3(0, 0, 5));
  EXPECT_TRUE(one(state, 0).seen) << toString(one(state, 0).reason);
  EXPECT_TRUE(one(state, 1).seen) << toString(one(state, 1).reason);
  EXPECT_EQ(one(state, 2).reason, NotSeenReason::OutsideVerticalFov);
}

TEST_F(ScorerTest, PointBehindCameraIsNotSeen) {
  build({facingMinusX(10, 0, 5)});
  CaptureState state = cameraAt(spec_, Vec3(5, 0, 5));
  state.yaw = 180 * kDeg;  // looking away from the wall, camera offset now behind the body
  // p_C = body + Rz(180) (0.2, 0, -0.3): place the body so the camera is at (5, 0, 5).
  state.position = Vec3(5.2, 0, 5.3);
  const PointScore ps = one(state);
  EXPECT_EQ(ps.reason, NotSeenReason::BehindCamera);
  EXPECT_FALSE(ps.seen);
  EXPECT_EQ(ps.score, 0.0);
}

TEST_F(ScorerTest, MeshOccluderHidesPointBehindIt) {
  // The panel at x = 5 spans |y| <= 1: the ray to (10, 0, 5) crosses it, the ray to (10, 3, 5)
  // passes it at y = 1.5.
  build({facingMinusX(10, 0, 5), facingMinusX(10, 3, 5)}, /*withPanel=*/true);
  const CaptureState state = cameraAt(spec_, Vec3(0, 0, 5));
  EXPECT_EQ(one(state, 0).reason, NotSeenReason::Occluded);
  EXPECT_TRUE(one(state, 1).seen) << toString(one(state, 1).reason);
}

TEST_F(ScorerTest, UavSphereAndBoxOccludePoints) {
  build({facingMinusX(10, -3, 5), facingMinusX(10, -5, 5)});
  const CaptureState state = cameraAt(spec_, Vec3(0, 0, 5));
  // Ray to (10, -3, 5) passes (5, -1.5, 5); ray to (10, -5, 5) passes (5, -2.5, 5), 1 m away.
  Occluders sphere;
  sphere.spheres.push_back({Vec3(5, -1.5, 5), 0.3});
  EXPECT_EQ(one(state, 0, sphere).reason, NotSeenReason::Occluded);
  EXPECT_TRUE(one(state, 1, sphere).seen);
  Occluders box;
  world::OrientedBox b;
  b.center = Vec3(5, -1.5, 5);
  b.size = Vec3(0.4, 0.4, 0.4);
  box.boxes.push_back(b);
  EXPECT_EQ(one(state, 0, box).reason, NotSeenReason::Occluded);
  EXPECT_TRUE(one(state, 1, box).seen);
  EXPECT_TRUE(one(state, 0).seen);  // and without occluders it is visible
}

TEST_F(ScorerTest, BatchedScoreAgreesWithSinglePointAndReportsOccluders) {
  build({facingMinusX(10, 0, 5), facingMinusX(10, 3, 5), facingMinusX(10, -3, 5),
         facingMinusX(10, 14, 5), facingMinusX(-5, 0, 5)},
        /*withPanel=*/true);
  Occluders occ;
  occ.spheres.push_back({Vec3(5, -1.5, 5), 0.3});
  const CaptureState state = cameraAt(spec_, Vec3(0, 0, 5));
  std::vector<PointScore> out;
  scorer_->score(spec_, state, occ, out);
  // (10, 14, 5) is 17.2 m away: beyond the 15.5 m radius, so not a candidate.
  ASSERT_EQ(out.size(), 4u);
  EXPECT_EQ(out[0].index, 0u);
  EXPECT_EQ(out[0].reason, NotSeenReason::Occluded);  // panel
  EXPECT_TRUE(out[1].seen);
  EXPECT_EQ(out[2].reason, NotSeenReason::Occluded);  // sphere
  EXPECT_EQ(out[3].index, 4u);
  EXPECT_EQ(out[3].reason, NotSeenReason::BehindCamera);
  for (const PointScore& ps : out) {
    const PointScore single = scorer_->scorePoint(spec_, state, occ, ps.index);
    EXPECT_EQ(single.reason, ps.reason);
    EXPECT_DOUBLE_EQ(single.score, ps.score);
  }
  EXPECT_EQ(scorer_->scorePoint(spec_, state, occ, 3).reason, NotSeenReason::OutOfRange);
}

TEST_F(ScorerTest, PointWithoutSurfaceFailsCaricButPassesStrict) {
  // The reference ray reports 1000 m when it hits nothing, so a point floating in the air is
  // never seen in caric mode; strict mode only asks that nothing is in between.
  world::InterestPoint floating = facingMinusX(5, 2, 5);
  build({floating}, false, ScoringMode::Caric);
  EXPECT_EQ(one(cameraAt(spec_, Vec3(0, 0, 5))).reason, NotSeenReason::NoSurfaceHit);
  build({floating}, false, ScoringMode::Strict);
  EXPECT_TRUE(one(cameraAt(spec_, Vec3(0, 0, 5))).seen);
}

TEST_F(ScorerTest, LateralSpeedBlurRuleOfThumb) {
  build({facingMinusX(10, 0, 5)});
  CaptureState state = cameraAt(spec_, Vec3(5, 0, 5));
  state.linearVelocity = Vec3(0, 2, 0);
  // f tau v / (c d) = 0.016 * 0.001 * 2 / (4.35e-6 * 5) = 1.47126 px -> q_blur = 0.67969.
  const PointScore ps = one(state);
  EXPECT_NEAR(ps.blurPixels, 1.47126, 1e-4);
  EXPECT_NEAR(ps.qBlur, 0.68, 1e-3);
  // Frontal at 5 m: 1.36 mm/px < 2, so q_res = 1 and the score is the blur alone.
  EXPECT_NEAR(ps.score, 0.67969, 1e-4);
}

TEST_F(ScorerTest, BlurIsTheLargerImageAxisShiftNotTheNorm) {
  build({facingMinusX(10, 0, 5)});
  CaptureState state = cameraAt(spec_, Vec3(5, 0, 5));
  state.linearVelocity = Vec3(0, 2, 2);
  // Each image axis shifts 3.678 * 2 / 5 = 1.47126 px; the reference keeps the larger one, not
  // the diagonal length 2.0807 px.
  EXPECT_NEAR(one(state).blurPixels, 1.47126, 1e-4);
}

TEST_F(ScorerTest, GimbalPitchRateBlursByFocalTimesExposureOverPixel) {
  build({facingMinusX(10, 0, 5)});
  CaptureState state = cameraAt(spec_, Vec3(5, 0, 5));
  state.gimbalPitchRate = 1.0;
  // The point on the axis moves tau * 1 rad: f tau / c = 3.678 px, at any distance.
  const PointScore ps = one(state);
  EXPECT_NEAR(ps.blurPixels, 3.678, 1e-3);
  EXPECT_NEAR(ps.qBlur, 1.0 / 3.678, 1e-3);
}

TEST_F(ScorerTest, BodyYawRateBlurIncludesCameraLeverArm) {
  build({facingMinusX(10, 0, 5)});
  CaptureState state = cameraAt(spec_, Vec3(5, 0, 5));
  state.angularVelocity = Vec3(0, 0, 1);
  // Rotation sweeps the point at 5 m/s, the 0.2 m lever moves the camera 0.2 m/s the other way
  // relative to it: 5.2 m/s at 5 m -> 3.678 * 1.04 = 3.8253 px.
  EXPECT_NEAR(one(state).blurPixels, 3.8253, 1e-3);
}

TEST_F(ScorerTest, ScoreOfExactlyThresholdCounts) {
  // A unit camera (f = c = tau = 1 m, s) makes the numbers exact: the point 1 m ahead moving
  // 5 m/s sideways shifts |0 - 5/1| = 5 px -> q_blur = 1/5 = 0.2 exactly; r_des is huge so
  // q_res = 1.
  build({facingMinusX(10, 0, 5)});
  spec_.focalLength = 1.0;
  spec_.pixelSize = 1.0;
  spec_.exposureTime = 1.0;
  spec_.desiredMmPerPixel = 1e6;
  spec_.positionInBody = Vec3::Zero();
  CaptureState state;
  state.position = Vec3(9, 0, 5);
  state.linearVelocity = Vec3(0, 5, 0);
  PointScore ps = one(state);
  ASSERT_TRUE(ps.seen) << toString(ps.reason);
  EXPECT_EQ(ps.qRes, 1.0);
  EXPECT_EQ(ps.score, 0.2);
  EXPECT_TRUE(ps.counted);
  state.linearVelocity = Vec3(0, 5.0001, 0);
  ps = one(state);
  EXPECT_LT(ps.score, 0.2);
  EXPECT_FALSE(ps.counted);
}

TEST(ResolutionFormula, CaricAndStrictAgreeOnFrontalView) {
  CameraSpec spec;
  const Vec3 q(6, 0, 0);
  const Vec3 n(-1, 0, 0);
  const double caric = resolutionMmPerPixel(spec, q, n, ScoringMode::Caric);
  const double strict = resolutionMmPerPixel(spec, q, n, ScoringMode::Strict);
  EXPECT_NEAR(caric, 0.271875 * 6, 1e-6);
  EXPECT_NEAR(strict, caric, 1e-9);
}

TEST(ResolutionFormula, CaricAndStrictAgreeOnSingleAxisTilt) {
  // n = (-0.6, 0.8, 0): caric d_v = (0, 0, -0.6) and d_u = (-0.8, -0.6, 0) both foreshorten by
  // 0.6; strict d_v = (0, 0, -1) is not foreshortened but d_u still is: same max.
  CameraSpec spec;
  const Vec3 q(6, 0, 0);
  const Vec3 n(-0.6, 0.8, 0);
  EXPECT_NEAR(resolutionMmPerPixel(spec, q, n, ScoringMode::Caric), 0.271875 * 6 / 0.6, 1e-5);
  EXPECT_NEAR(resolutionMmPerPixel(spec, q, n, ScoringMode::Strict), 0.271875 * 6 / 0.6, 1e-5);
}

TEST(ResolutionFormula, CaricPenalisesObliqueNormalMoreThanStrict) {
  // n = (-0.6, 0.48, 0.64), point on the axis at 6 m. A displacement e gives |e_z| / d (or
  // |e_y| / d) of image shift per metre, so mm/px = 0.271875 * 6 / |e_z|.
  // Caric: d_v = (-0.64, 0, -0.6), d_u = (-0.48, -0.6, 0): both 0.6 -> 2.71875 mm/px, q 0.73563.
  // Strict: d_v z = 0.6 / sqrt(0.36 + 0.4096) = 0.68394 -> 2.38507 mm/px;
  //         d_u y = 0.6 / sqrt(0.36 + 0.2304) = 0.78088 -> 2.08891 mm/px; max 2.38507, q 0.83855.
  CameraSpec spec;
  const Vec3 q(6, 0, 0);
  const Vec3 n(-0.6, 0.48, 0.64);
  const double caric = resolutionMmPerPixel(spec, q, n, ScoringMode::Caric);
  const double strict = resolutionMmPerPixel(spec, q, n, ScoringMode::Strict);
  EXPECT_NEAR(caric, 2.71875, 1e-5);
  EXPECT_NEAR(strict, 2.38507, 1e-5);
  EXPECT_NEAR(resolutionQuality(spec, caric), 0.73563, 1e-5);
  EXPECT_NEAR(resolutionQuality(spec, strict), 0.83855, 1e-5);
}

TEST(ResolutionFormula, BackFacingNormalIsScoredLikeFrontFacing) {
  // No back-face test in the reference: only |n_x| enters.
  CameraSpec spec;
  const Vec3 q(6, 0, 0);
  EXPECT_NEAR(resolutionMmPerPixel(spec, q, Vec3(1, 0, 0), ScoringMode::Caric),
              resolutionMmPerPixel(spec, q, Vec3(-1, 0, 0), ScoringMode::Caric), 1e-12);
}

TEST(ResolutionFormula, EdgeOnSurfaceHasZeroQuality) {
  CameraSpec spec;
  // Normal (0, 0, 1) on the axis: d_v = (-1, 0, 0) moves along the ray, z stays 0 -> infinite
  // mm/px -> q_res = 0.
  const double mm = resolutionMmPerPixel(spec, Vec3(6, 0, 0), Vec3(0, 0, 1), ScoringMode::Caric);
  EXPECT_TRUE(std::isinf(mm));
  EXPECT_EQ(resolutionQuality(spec, mm), 0.0);
}

TEST(ResolutionFormula, ProbeBehindCameraIsDegenerate) {
  CameraSpec spec;
  // 0.1 mm in front of the camera with a normal along y: d_u = (-1, 0, 0) puts one probe at
  // x = -0.4 mm.
  EXPECT_TRUE(std::isnan(
      resolutionMmPerPixel(spec, Vec3(0.0001, 0, 0), Vec3(0, 1, 0), ScoringMode::Caric)));
}

TEST(BlurFormula, NoMotionGivesFullQuality) {
  CameraSpec spec;
  EXPECT_EQ(blurPixels(spec, Vec3(5, 1, 1), Vec3::Zero()), 0.0);
  EXPECT_EQ(blurQuality(0.0), 1.0);
  EXPECT_EQ(blurQuality(0.5), 1.0);  // under one pixel is capped at 1
  EXPECT_EQ(blurQuality(4.0), 0.25);
}

TEST(ScoringModeText, ParsesAndPrints) {
  EXPECT_EQ(parseScoringMode("caric", "--mode"), ScoringMode::Caric);
  EXPECT_EQ(parseScoringMode("strict", "--mode"), ScoringMode::Strict);
  EXPECT_STREQ(toString(ScoringMode::Strict), "strict");
  EXPECT_THROW(parseScoringMode("paper", "--mode"), InputError);
}

}  // namespace
}  // namespace coinspect::sensing
