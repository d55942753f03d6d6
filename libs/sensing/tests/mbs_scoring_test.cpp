// Scoring on the real CARIC MBS scenario (read from ../shared, never copied).
#include <gtest/gtest.h>

#include <memory>

#include "coinspect/sensing/inspection_scorer.h"
#include "coinspect/testing/paths.h"
#include "coinspect/world/caric_scenario.h"
#include "coinspect/world/ray_caster.h"

namespace coinspect::sensing {
namespace {

class MbsScoring : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    if (!testing::haveCaricMbs()) return;
    scenario_ =
        std::make_unique<world::Scenario>(world::importCaricScenario(testing::caricMbsDir()));
    caster_ = std::make_unique<world::RayCaster>(scenario_->meshes, scenario_->groundZ);
  }
  static void TearDownTestSuite() {
    caster_.reset();
    scenario_.reset();
  }

  static const world::CameraSpec& photographerCamera() {
    for (const world::UnitSpec& unit : scenario_->fleet) {
      if (unit.role == world::UnitRole::Photographer) return unit.camera;
    }
    return scenario_->fleet.back().camera;
  }

  static std::unique_ptr<world::Scenario> scenario_;
  static std::unique_ptr<world::RayCaster> caster_;
};

std::unique_ptr<world::Scenario> MbsScoring::scenario_;
std::unique_ptr<world::RayCaster> MbsScoring::caster_;

TEST_F(MbsScoring, CameraFiveMetresAlongNormalScoresThePoint) {
  COINSPECT_REQUIRE_CARIC_MBS();
  const world::CameraSpec& spec = photographerCamera();
  ASSERT_DOUBLE_EQ(spec.desiredMmPerPixel, 2.0);
  InspectionScorer scorer(scenario_->interestPoints, *caster_, ScoringMode::Caric);
  const size_t n = scenario_->interestPoints.size();
  ASSERT_GT(n, 1000u);
  // Static and frontal at 5 m: 0.271875 * 5 = 1.36 mm/px < 2 -> q_res = 1, q_blur = 1, so the
  // score is 1 unless something stands within 5 m in front of the surface. Points spread over
  // the index range; every one must be seen except where the 5 m stand-off line is blocked,
  // which the test checks independently with a plain segment test.
  std::vector<PointScore> out;
  size_t checked = 0;
  for (size_t i = 0; i < n; i += n / 80) {
    const world::InterestPoint& p = scenario_->interestPoints[i];
    const CaptureState state = aimCamera(spec, p.position, -p.normal, 5.0);
    const Vec3 camera = cameraPose(spec, state).position;
    // Blocked by construction: the stand-off line (camera to 1 cm above the surface) hits
    // other geometry, or the camera would be underground.
    const Vec3 nearPoint = p.position + 0.01 * p.normal;
    if (!caster_->segmentClear(camera, nearPoint, 0.0) || camera.z() < scenario_->groundZ) {
      continue;
    }
    ++checked;
    const PointScore ps = scorer.scorePoint(spec, state, Occluders{}, p.index);
    EXPECT_TRUE(ps.seen) << "point " << i << ": " << toString(ps.reason);
    EXPECT_GT(ps.score, 0.9) << "point " << i;
    // The batched path gives the same verdict for this point.
    scorer.score(spec, state, Occluders{}, out);
    bool found = false;
    for (const PointScore& candidate : out) {
      if (candidate.index != p.index) continue;
      found = true;
      EXPECT_EQ(candidate.seen, ps.seen) << "point " << i;
      EXPECT_DOUBLE_EQ(candidate.score, ps.score) << "point " << i;
    }
    EXPECT_TRUE(found) << "point " << i;
  }
  // About half of the sampled stand-off lines are free: the towers are built of several shells
  // (facade fins, double skins), so many points face another surface within 5 m.
  EXPECT_GE(checked, 25u);
}

}  // namespace
}  // namespace coinspect::sensing
