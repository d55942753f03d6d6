// The slei3d inspector driven by hand on a perfect vehicle: given a feature its explorer detected
// from the side (a grazing line of sight), it first inspects it from its own view in front of the
// feature, then, the feature still not inspected after its patience, from the detection pose;
// caric-team's inspector skips a feature whose result reaches it on the way, slei3d's does not.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
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
// `frame`, when given, reaches it as a teammate's key frame before its orders do (which then
// come at 2 s, after its map has taken the frame in). `resultAt`, when >= 0, is when the
// feature's inspection result reaches it (another inspector's, carried by its explorer).
std::vector<Vec3> fly(double until, const std::string& ini = "",
                      const agent::KeyFrameView& frame = nullptr, double resultAt = -1.0,
                      const std::string& strategy = "slei3d") {
  static agent::StrategyRegistry registry = [] {
    agent::StrategyRegistry r;
    registerSlei3d(r);
    return r;
  }();
  const auto config = Config::fromText(ini, "run.ini");
  auto inspector = registry.create(strategy, agent::StrategyContext{config,
                                                                    strategy,
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
    view.receivedKeyFrames.clear();
    view.receivedResults.clear();
    if (resultAt >= 0.0 && step == static_cast<int>(std::lround(resultAt * 10.0)))
      view.receivedResults.push_back(7);
    if (step == 0) view.messages.push_back({"gcs", kPlanTopic, encode(plan)});
    if (step == 0 && frame) view.receivedKeyFrames.push_back(frame);
    if (step == (frame ? 20 : 1)) view.messages.push_back({"e1", kOrdersTopic, encode(orders)});
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

// The feature's result reaches it on its way to the feature: caric-team's inspector holds at
// neither pose; slei3d's still inspects from in front of the feature (its explorer, which
// carries the same results, hands none of them out; skipping slowed slei3d's collection).
TEST(Slei3dInspector, OnlyCaricTeamSkipsAFeatureWhoseResultItReceived) {
  const Vec3 ownView = kFeature + Vec3(0, -3, 0);
  const auto team = fly(40.0, "", nullptr, 1.5, "caric-team");
  for (size_t t = 0; t < team.size(); ++t) {
    EXPECT_GT((team[t] - ownView).norm(), 0.5) << t << " s";
    EXPECT_GT((team[t] - kDetectedFrom).norm(), 0.5) << t << " s";
  }
  const auto slei3d = fly(40.0, "", nullptr, 1.5);
  EXPECT_TRUE(std::any_of(slei3d.begin(), slei3d.end(),
                          [&](const Vec3& p) { return (p - ownView).norm() < 1.0; }));
}

// A fin 0.5 m thick standing out of the face from the feature's side to 7 m in front of it, seen
// by a teammate's LiDAR: no place on the normal's line has the flight's clearance.
agent::KeyFrameView finInFront() {
  auto frame = std::make_shared<agent::KeyFrame>();
  frame->producer = "e1";
  frame->position = Vec3(5, 3, 2);
  for (double y = 1.0; y <= 7.6; y += 0.25)
    for (double z = 0.25; z <= 4.0; z += 0.25)
      frame->points.emplace_back(0.2f, static_cast<float>(y), static_cast<float>(z));
  return frame;
}

TEST(Slei3dInspector, WithObliqueViewsTurnsAwayFromABlockedNormalBeforeTheDetectionPose) {
  const auto heldAt = [](const std::vector<Vec3>& at) {  // the first place held for 5 s
    for (size_t t = 5; t < at.size(); ++t)
      if ((at[t] - at[t - 5]).norm() < 0.05) return at[t];
    return Vec3(Vec3::Constant(1e9));
  };
  // Without the option the blocked own view is given up at once: the detection pose first.
  const Vec3 plain = heldAt(fly(40.0, "", finInFront()));
  EXPECT_LT((plain - kDetectedFrom).norm(), 0.5) << plain.transpose();
  // With it: a place beside the fin (either side: the map does not know its far side, which is
  // open away from the box), off the normal by less than 60 deg, in front of the face.
  const Vec3 oblique = heldAt(fly(40.0, "[slei3d]\noblique_views = true\n", finInFront()));
  EXPECT_GT((oblique - kDetectedFrom).norm(), 2.0) << oblique.transpose();
  EXPECT_GT(std::abs(oblique.x()), 1.0) << oblique.transpose();
  EXPECT_LT(oblique.y(), kFeature.y() - 1.0);
  const Vec3 seen = (oblique - kFeature).normalized();
  EXPECT_LT(std::acos(seen.dot(Vec3(0, -1, 0))), 60.0 * M_PI / 180.0);
}

}  // namespace
}  // namespace coinspect::strategies::slei
