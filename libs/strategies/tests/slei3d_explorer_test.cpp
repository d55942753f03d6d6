// The slei3d explorer driven by hand on a perfect vehicle: with its next box reserved, an
// explorer done with its box goes on to the next one before its station meeting; without one, it
// looks for a late station along the station's route.
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

// A 4 m box by the start and another one 40 m away: nothing is ever scanned, so the explorer's
// map holds neither surface nor frontier, and a box is explored as soon as it is there.
const std::vector<agent::BoxView> kBoxes = {makeBox(Vec3(0, 10, 2), Vec3(4, 4, 4)),
                                            makeBox(Vec3(40, 10, 2), Vec3(4, 4, 4))};

struct Run {
  std::unique_ptr<agent::Strategy> explorer;
  agent::AgentView view;
  double closestToSecondBox = 1e300;  // m, horizontal, over the whole run
};

Vec3 cornerOf(size_t box) {
  return boxCorner(kBoxes, box, 2.0, 0.0, Vec3(0, 0, 0));
}

// e1 explores box 0; its meeting with the station (never in range) is at 400 s at box 0's
// corner; a reply at 1 s (as if met on the way) optionally reserves box 1, and lists the
// station's stops before that meeting (`before`).
Run fly(const Config& config, int32_t reserved, double until, std::vector<Meeting> before = {}) {
  static agent::StrategyRegistry registry = [] {
    agent::StrategyRegistry r;
    registerSlei3d(r);
    return r;
  }();
  Run run;
  run.explorer = registry.create(
      "slei3d", agent::StrategyContext{config,
                                       "slei3d",
                                       "e1",
                                       Role::Explorer,
                                       1,
                                       1,
                                       {{"gcs", Role::GroundStation}, {"e1", Role::Explorer}},
                                       {},
                                       0.5});
  const Vec3 corner = cornerOf(0);
  FleetPlan plan;
  plan.subgroups.push_back({1, {}, 0, {corner, 400.0}, 0});
  Reply reply;
  reply.meetingNumber = 1;
  reply.box = 0;
  reply.next = {corner, 400.0};
  reply.stops = before;
  reply.stops.push_back(reply.next);
  reply.nextBox = reserved;
  auto& view = run.view;
  view.name = "e1";
  view.role = Role::Explorer;
  view.alive = true;
  view.boxes = &kBoxes;
  view.odometry.position = Vec3(0, 0, 0.1);
  for (int step = 0; step * 0.1 <= until; ++step) {
    view.time = step * 0.1;
    view.messages.clear();
    if (step == 0) view.messages.push_back({"gcs", kPlanTopic, encode(plan)});
    if (step == 10) view.messages.push_back({"gcs", kReplyTopic, encode(reply)});
    const auto command = run.explorer->decide(view);
    if (command.setpoint) view.odometry.position = command.setpoint->position;
    run.closestToSecondBox = std::min(run.closestToSecondBox,
                                      (view.odometry.position - kBoxes[1].center).head<2>().norm());
  }
  return run;
}

TEST(Slei3dExplorer, DoneWithItsBoxItGoesOnToTheReservedOne) {
  const auto config = Config::fromText("", "run.ini");
  // Reserved: long before its 400 s meeting it is at box 1's corner (2 m out in x and y: 5.7 m
  // from the centre).
  EXPECT_LT(fly(config, 1, 120.0).closestToSecondBox, 8.0);
  // Nothing reserved (or the paper's rule): it stays by box 0, 40 m away, for its meeting.
  EXPECT_GT(fly(config, -1, 120.0).closestToSecondBox, 30.0);
}

// Done early without a box reserved, it goes where it expects the station soonest: its own
// meeting place, once the station is through with its stop at box 1 (at 20 s, too soon for the
// explorer to catch it there). The station is not there (it stayed on at box 1): the explorer
// goes back along the station's route and looks for it at box 1's stop.
TEST(Slei3dExplorer, TheStationLateItLooksForItAtTheStopBefore) {
  const auto config = Config::fromText("", "run.ini");
  const std::vector<Meeting> before = {{cornerOf(1), 20.0}};
  EXPECT_GT(fly(config, -1, 100.0, before).closestToSecondBox, 30.0);  // at its own place first
  EXPECT_LT(fly(config, -1, 250.0, before).closestToSecondBox, 8.0);   // then at box 1's stop
}

}  // namespace
}  // namespace coinspect::strategies::slei
