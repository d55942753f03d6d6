#include "coinspect/eval/view_bound.h"

#include <gtest/gtest.h>

#include "../../world/tests/test_meshes.h"
#include "coinspect/core/error.h"

namespace coinspect::eval {
namespace {

using world::Vec3;

// Two blocks 1 m apart: points on the open front face of the first (x = 0, facing -x) and on its
// face inside the 1 m slot (x = 4, facing +x, 10 m below the top and from the slot's ends).
world::Scenario slotScene() {
  world::Scenario scenario;
  scenario.name = "slot";
  scenario.meshes = {world::test::boxMesh(Vec3(0, -10, 0), Vec3(4, 10, 20), "front"),
                     world::test::boxMesh(Vec3(5, -10, 0), Vec3(9, 10, 20), "back")};
  std::vector<world::InterestPoint> points;
  for (const double y : {-4.0, 0.0, 4.0})
    for (const double z : {6.0, 10.0, 14.0})
      points.push_back({Vec3(0, y, z), -Vec3::UnitX(), 0});
  for (const double y : {-2.0, 0.0, 2.0})
    points.push_back({Vec3(4, y, 10), Vec3::UnitX(), 0});
  scenario.interestPoints = world::InterestPointSet(std::move(points));
  return scenario;
}

TEST(ViewBound, PointsInAGapNarrowerThanTheClearanceAreOutOfReach) {
  const auto scenario = slotScene();
  const world::RayCaster caster(scenario.meshes, scenario.groundZ);
  ViewBoundOptions options;
  options.clearances = {0.0, 1.0, 3.0};
  options.distances = {0.5, 4.0, 7.0};  // 0.5 m: a camera inside the slot
  const auto rows =
      staticViewBound(scenario, caster, world::CameraSpec{}, sensing::ScoringMode::Caric, options);
  ASSERT_EQ(rows.size(), 3u);
  EXPECT_EQ(rows[0].clearance, 0.0);
  EXPECT_EQ(rows[0].detected, 12u);  // the slot is seen from inside it
  EXPECT_EQ(rows[1].detected, 9u);   // not with 1 m of clearance: the slot is 1 m wide
  EXPECT_EQ(rows[2].detected, 9u);   // the front is seen from 4 and 7 m
  // Frontal views from 4 m of a static camera score 1 per point.
  EXPECT_NEAR(rows[1].score, 9.0, 1e-9);
  EXPECT_NEAR(rows[0].score, 12.0, 1e-9);
  EXPECT_GT(rows[0].views, rows[1].views);
  EXPECT_GE(rows[1].views, rows[2].views);
}

TEST(ViewBound, RejectsEmptyOrNegativeLists) {
  const auto scenario = slotScene();
  const world::RayCaster caster(scenario.meshes, scenario.groundZ);
  ViewBoundOptions options;
  options.clearances = {};
  EXPECT_THROW(staticViewBound(scenario, caster, {}, sensing::ScoringMode::Caric, options),
               InputError);
  options.clearances = {1.0, -1.0};
  EXPECT_THROW(staticViewBound(scenario, caster, {}, sensing::ScoringMode::Caric, options),
               InputError);
  options.clearances = {1.0};
  options.distances = {0.0};
  EXPECT_THROW(staticViewBound(scenario, caster, {}, sensing::ScoringMode::Caric, options),
               InputError);
}

}  // namespace
}  // namespace coinspect::eval
