// The slei3d inspector driven by hand on a perfect vehicle: given a feature its explorer detected
// from the side (a grazing line of sight), it first inspects it from its own view in front of the
// feature, then, the feature still not inspected after its patience, from the detection pose.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "coinspect/strategies/slei/fleet_plan.h"
#include "coinspect/strategies/slei/slei3d_strategy.h"
#include "test_boxes.h"

namespace coinspect::strategies::slei {
namespace {

using agent::Role;
using test::makeBox;

// A 4 m box whose south face (y = 8) holds the feature, 2 m up, facing -y.
const std::vector<agent::BoxView> kBoxes = {makeBox(Vec3(0, 10, 2), Vec3(4, 4, 4))};
const Vec3 kFeature(0, 8, 2);
const Vec3 kDetectedFrom(7, 7.5, 2);  // 7 m along the face: cos(normal, line of sight) = 0.07

agent::CameraInfo caricCamera() {
  agent::CameraInfo c;
  c.horizontalFov = 80.0 * M_PI / 180.0;
  c.verticalFov = 60.0 * M_PI / 180.0;
  c.positionInBody = Vec3(0.2, 0.0, -0.3);
  c.focalLength = 0.016;
  c.pixelSize = 4.35e-6;
  c.desiredMmPerPixel = 2.0;
  return c;
}

// Where the inspector is at each whole second, up to `until`; the feature is never inspected.
std::vector<Vec3> fly(double until) {
  static agent::StrategyRegistry registry = [] {
    agent::StrategyRegistry r;
    registerSlei3d(r);
    return r;
  }();
  const auto config = Config::fromText("", "run.ini");
  auto inspector = registry.create("slei3d", agent::StrategyContext{config,
                                                                    "slei3d",
                                                                    "i1",
                                                                    Role::Photographer,
                                                                    2,
                                                                    1,
                                                                    {{"gcs", Role::GroundStation},
                                                                     {"e1", Role::Explorer},
                                                                     {"i1", Role::Photographer}},
                                                                    caricCamera(),
                                                                    0.5});
  FleetPlan plan;
  plan.subgroups.push_back({1, {2}, 0, {Vec3(-4, 6, 0), 400.0}, 0});
  Orders orders;
  orders.sequence = 1;
  FeatureTask task;
  task.id = 7;
  task.position = kFeature;
  task.normal = Vec3(0, -1, 0);
  task.viewPosition = kDetectedFrom;
  orders.tasks.push_back(task);
  agent::AgentView view;
  view.name = "i1";
  view.role = Role::Photographer;
  view.alive = true;
  view.boxes = &kBoxes;
  view.odometry.position = Vec3(-4, 2, 0.1);
  std::vector<Vec3> at;
  for (int step = 0; step * 0.1 <= until; ++step) {
    view.time = step * 0.1;
    view.messages.clear();
    if (step == 0) view.messages.push_back({"gcs", kPlanTopic, encode(plan)});
    if (step == 1) view.messages.push_back({"e1", kOrdersTopic, encode(orders)});
    const auto command = inspector->decide(view);
    if (command.setpoint) view.odometry.position = command.setpoint->position;
    if (step % 10 == 0) at.push_back(view.odometry.position);
  }
  return at;
}

TEST(Slei3dInspector, InspectsFromInFrontOfTheFeatureThenFromWhereItWasDetected) {
  const auto at = fly(90.0);
  // Its own view: 3 m out along the normal (the body pushed by the camera's offset). It holds
  // there for a while (a flight past it does not count), then holds at the detection pose.
  const Vec3 ownView = kFeature + Vec3(0, -3, 0);
  int inFront = 0, atDetection = 0, firstAtDetection = -1, lastInFront = -1;
  for (size_t t = 0; t < at.size(); ++t) {
    if ((at[t] - ownView).norm() < 1.0) {
      ++inFront;
      lastInFront = static_cast<int>(t);
    }
    if ((at[t] - kDetectedFrom).norm() < 0.5) {
      ++atDetection;
      if (firstAtDetection < 0) firstAtDetection = static_cast<int>(t);
    }
  }
  EXPECT_GE(inFront, 8);  // s; the patience is 12 s
  EXPECT_GE(atDetection, 8);
  EXPECT_GT(firstAtDetection, lastInFront);
}

}  // namespace
}  // namespace coinspect::strategies::slei
