#include "coinspect/sensing/feature_detection.h"

#include <gtest/gtest.h>

#include <cmath>

#include "coinspect/testing/input_errors.h"
#include "sensing_scenes.h"

namespace coinspect::sensing {
namespace {

using test::facingMinusX;
using test::wallX;

// A wall at x = 3 facing the origin with features on it, plus a small panel at x = 1.5 that
// hides the feature at (3, -0.6, 1) from (0, 0, 1).
struct Scene {
  world::RayCaster caster{{wallX(3.0, -10.0, 10.0, 0.0, 6.0), wallX(1.5, -0.5, -0.1, 0.8, 1.2)},
                          std::nullopt};
  world::InterestPointSet features{{facingMinusX(3.0, 0.0, 1.0),    // 0: straight ahead
                                    facingMinusX(3.0, -0.6, 1.0),   // 1: behind the panel
                                    facingMinusX(3.0, 2.1, 1.0),    // 2: 35 deg to the left
                                    facingMinusX(3.0, 3.3, 1.0),    // 3: 47.7 deg: outside
                                    facingMinusX(3.0, 0.0, 2.85),   // 4: 31.7 deg up: outside
                                    facingMinusX(3.0, 0.0, 2.5)}};  // 5: 26.6 deg up
};

std::vector<uint32_t> detect(const Scene& scene, const world::Vec3& at, double yaw,
                             FeatureSensor sensor = {}) {
  std::vector<uint32_t> found{99};  // cleared by the call
  detectFeatures(sensor, at, yaw, scene.features, scene.caster, found);
  return found;
}

using Found = std::vector<uint32_t>;

TEST(FeatureDetection, FieldOfViewAndOcclusionDecide) {
  const Scene scene;
  EXPECT_EQ(detect(scene, {0, 0, 1}, 0.0), (Found{0, 2, 5}));
  // Without the panel the hidden one is found: occlusion, not the field of view, dropped it.
  Scene open;
  open.caster = world::RayCaster({wallX(3.0, -10.0, 10.0, 0.0, 6.0)}, std::nullopt);
  EXPECT_EQ(detect(open, {0, 0, 1}, 0.0), (Found{0, 1, 2, 5}));
  // A wider sensor takes the two at the field's edges too.
  FeatureSensor wide;
  wide.halfYaw = 50.0 * M_PI / 180.0;
  wide.halfElevation = 33.0 * M_PI / 180.0;
  EXPECT_EQ(detect(open, {0, 0, 1}, 0.0, wide), (Found{0, 1, 2, 3, 4, 5}));
}

TEST(FeatureDetection, HeadingAndRangeLimitWhatIsFound) {
  const Scene scene;
  EXPECT_TRUE(detect(scene, {0, 0, 1}, M_PI).empty());  // facing away
  // Turned 30 deg left: 3 (47.7 deg left) comes in, 0 is at the right edge (30 deg).
  EXPECT_EQ(detect(scene, {0, 0, 1}, M_PI / 6), (Found{0, 2, 3, 5}));
  // From 5.5 m back nothing lies within the 5 m range; a 6 m range finds four (1 still hidden).
  EXPECT_TRUE(detect(scene, {-2.5, 0, 1}, 0.0).empty());
  FeatureSensor far;
  far.range = 6.0;
  EXPECT_EQ(detect(scene, {-2.5, 0, 1}, 0.0, far), (Found{0, 2, 4, 5}));
}

TEST(FeatureDetection, AFeatureSeenFromBehindItsSurfaceIsNotDetected) {
  // No mesh at all, so only the facing test can drop it: its normal points away from (0, 0, 1).
  world::InterestPoint back = facingMinusX(3.0, 0.0, 1.0);
  back.normal = world::Vec3(1, 0, 0);
  Scene scene;
  scene.caster = world::RayCaster({}, std::nullopt);
  scene.features = world::InterestPointSet({back});
  EXPECT_TRUE(detect(scene, {0, 0, 1}, 0.0).empty());
  EXPECT_EQ(detect(scene, {5, 0, 1}, M_PI), (Found{0}));
}

// The reference code's detector (no line of sight, no facing test): the feature behind the panel
// and one seen from behind its surface are found; the field of view and range still decide.
TEST(FeatureDetection, WithoutTheLineOfSightTestOnlyTheFieldOfViewAndRangeDecide) {
  FeatureSensor reference;
  reference.lineOfSight = false;
  const Scene scene;
  EXPECT_EQ(detect(scene, {0, 0, 1}, 0.0, reference), (Found{0, 1, 2, 5}));
  EXPECT_TRUE(detect(scene, {0, 0, 1}, M_PI, reference).empty());
  EXPECT_TRUE(detect(scene, {-2.5, 0, 1}, 0.0, reference).empty());
  world::InterestPoint back = facingMinusX(3.0, 0.0, 1.0);
  back.normal = world::Vec3(1, 0, 0);
  Scene behind;
  behind.features = world::InterestPointSet({back});
  EXPECT_EQ(detect(behind, {0, 0, 1}, 0.0, reference), (Found{0}));
  EXPECT_TRUE(detect(behind, {0, 0, 1}, 0.0).empty());
}

TEST(InspectionTimer, ARunOfConsecutiveCapturesSpanningTheDurationInspects) {
  InspectionTimer timer(3, 0.3);
  std::vector<uint32_t> done;
  timer.capture(0.0, {0, 1}, done);
  timer.capture(0.1, {0, 1}, done);
  timer.capture(0.2, {0}, done);  // 1's run ends here
  EXPECT_TRUE(done.empty());
  timer.capture(0.3, {0, 1}, done);  // 0: 0.0 .. 0.3 done; 1 starts again
  EXPECT_EQ(done, (Found{0}));
  timer.capture(0.4, {0, 1}, done);
  timer.capture(0.5, {0, 1}, done);
  EXPECT_EQ(done, (Found{0}));  // 0 only once
  timer.capture(0.6, {1}, done);
  EXPECT_EQ(done, (Found{0, 1}));
  EXPECT_TRUE(timer.inspected(1));
  EXPECT_FALSE(timer.inspected(2));
  // A zero duration inspects at the first capture.
  InspectionTimer instant(1, 0.0);
  done.clear();
  instant.capture(7.0, {0}, done);
  EXPECT_EQ(done, (Found{0}));
}

TEST(InspectionTimer, RejectsABadDuration) {
  EXPECT_THROW(InspectionTimer(1, -1.0), InputError);
  EXPECT_THROW(InspectionTimer(1, std::nan("")), InputError);
}

}  // namespace
}  // namespace coinspect::sensing
