// The slei3d ground station driven by hand: the unknown workspace's slabs and octree parts, the
// reserved next box (and the last free box kept for an explorer without one).
#include <gtest/gtest.h>

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "coinspect/strategies/slei/fleet_plan.h"
#include "coinspect/strategies/slei/slei3d_strategy.h"
#include "coinspect/testing/input_errors.h"
#include "test_boxes.h"

namespace coinspect::strategies::slei {
namespace {

using agent::Role;
using test::makeBox;

agent::StrategyContext stationContext(const Config& config) {
  return agent::StrategyContext{config,
                                "slei3d",
                                "gcs",
                                Role::GroundStation,
                                0,
                                1,
                                {{"gcs", Role::GroundStation},
                                 {"e1", Role::Explorer},
                                 {"e2", Role::Explorer},
                                 {"p1", Role::Photographer},
                                 {"p2", Role::Photographer}},
                                {},
                                0.0};
}

// Two 10 m cubes 30 m apart: the workspace is x in [-5, 35], y in [-5, 5], z in [0, 10].
const std::vector<agent::BoxView> kBoxes = {makeBox(Vec3(0, 0, 5), Vec3(10, 10, 10)),
                                            makeBox(Vec3(30, 0, 5), Vec3(10, 10, 10))};

agent::AgentView stationView(double time, const std::vector<agent::ReceivedMessage>& messages,
                             const std::vector<agent::BoxView>* boxes = &kBoxes) {
  agent::AgentView view;
  view.name = "gcs";
  view.role = Role::GroundStation;
  view.alive = true;
  view.boxes = boxes;
  view.time = time;
  view.odometry.position = Vec3(15, -15, 0.1);
  view.neighbours = {{"e1", Role::Explorer, {}}, {"e2", Role::Explorer, {}}};
  view.messages = messages;
  return view;
}

template <class T, class Decode>
std::optional<T> sent(const agent::AgentCommand& command, const std::string& to,
                      const std::string& topic, Decode decode) {
  for (const auto& m : command.messages)
    if (m.to == to && m.topic == topic) return decode(m.bytes);
  return std::nullopt;
}

bool sameBox(const agent::BoxView& a, const agent::BoxView& b) {
  return a.center.isApprox(b.center, 1e-9) && a.size.isApprox(b.size, 1e-9);
}

TEST(Slei3dStation, TheUnknownWorkspaceGivesSlabsThenThePartsLeftOfABox) {
  const auto config = Config::fromText("[slei3d]\nworkspace = unknown\n", "run.ini");
  auto strategy = agent::StrategyRegistry{};
  registerSlei3d(strategy);
  auto station = strategy.create("slei3d", stationContext(config));
  // The first plan: one 20 x 10 x 10 slab per explorer, across x; the first meetings at their
  // corners 2 m outside.
  const auto first = station->decide(stationView(0.0, {}));
  std::optional<FleetPlan> plan;
  for (const auto& m : first.messages)
    if (m.topic == kPlanTopic) plan = decodePlan(m.bytes);
  ASSERT_TRUE(plan);
  ASSERT_EQ(plan->subgroups.size(), 2u);
  const auto slabs = splitWorkspace(workspaceBox(kBoxes), 2);
  ASSERT_EQ(slabs.size(), 2u);
  EXPECT_TRUE(slabs[0].size.isApprox(Vec3(20, 10, 10), 1e-9));
  std::vector<int32_t> boxes;
  for (const auto& s : plan->subgroups) {
    ASSERT_GE(s.box, 0);
    ASSERT_LT(s.box, 2);
    boxes.push_back(s.box);
    const Vec3 corner = s.firstMeeting.place;
    EXPECT_NEAR(std::abs(corner.y()), 7.0, 1e-9);  // outside the workspace's long sides
  }
  EXPECT_NE(boxes[0], boxes[1]);

  // e1 reports its slab not done, with both halves (its octree parts) still holding work: it
  // goes on with the half nearest the station, a new box; the other half is free.
  Report report;
  report.box = boxes[0];
  report.remaining = 200.0;
  report.meetingNumber = 1;
  report.remainder = octreeChildren(slabs[static_cast<size_t>(boxes[0])], 10.0);
  ASSERT_EQ(report.remainder.size(), 2u);
  const auto second = station->decide(stationView(60.0, {{"e1", kReportTopic, encode(report)}}));
  const auto reply = sent<Reply>(second, "e1", kReplyTopic, decodeReply);
  ASSERT_TRUE(reply);
  ASSERT_TRUE(reply->boxShape);
  const Vec3 here(15, -15, 0.1);
  const size_t nearIndex = (report.remainder[0].center - here).head<2>().norm() <
                                   (report.remainder[1].center - here).head<2>().norm()
                               ? 0
                               : 1;
  const agent::BoxView near = report.remainder[nearIndex];
  const agent::BoxView far = report.remainder[1 - nearIndex];
  EXPECT_EQ(reply->box, static_cast<int32_t>(2 + nearIndex));  // the parts follow the slabs
  EXPECT_TRUE(sameBox(*reply->boxShape, near));
  EXPECT_DOUBLE_EQ(reply->next.time, 160.0);  // its half of the 200 s eq. 9 gave the slab
  // Its nearest corner, 2 m out; nothing learnt blocks the ground there.
  const Vec3 corner = boxCorner(near, 2.0, here.z(), here);
  EXPECT_LT((reply->next.place - corner).head<2>().norm(), 0.36);

  // While a box as large is free, a box with work left is not split again.
  report.box = reply->box;
  report.meetingNumber = 2;
  report.remainder = octreeChildren(near, 5.0);
  const auto kept =
      sent<Reply>(station->decide(stationView(160.0, {{"e1", kReportTopic, encode(report)}})), "e1",
                  kReplyTopic, decodeReply);
  ASSERT_TRUE(kept);
  EXPECT_EQ(kept->box, reply->box);

  // e2 done with its slab: the free half is the nearest box left (rolling assignment).
  Report done;
  done.box = boxes[1];
  done.boxFinished = true;
  done.meetingNumber = 1;
  const auto third = station->decide(stationView(170.0, {{"e2", kReportTopic, encode(done)}}));
  const auto toE2 = sent<Reply>(third, "e2", kReplyTopic, decodeReply);
  ASSERT_TRUE(toE2 && toE2->boxShape);
  EXPECT_EQ(toE2->box, static_cast<int32_t>(3 - nearIndex));
  EXPECT_TRUE(sameBox(*toE2->boxShape, far));

  // None free now: e1's half is split at its next meeting.
  report.meetingNumber = 3;
  const auto split =
      sent<Reply>(station->decide(stationView(220.0, {{"e1", kReportTopic, encode(report)}})), "e1",
                  kReplyTopic, decodeReply);
  ASSERT_TRUE(split && split->boxShape);
  EXPECT_GE(split->box, 4);
  EXPECT_LT(split->boxShape->size.maxCoeff(), 5.01);
}

TEST(Slei3dStation, WithTheBoxesKnownAReportedRemainderChangesNothing) {
  const auto config = Config::fromText("", "run.ini");
  auto strategy = agent::StrategyRegistry{};
  registerSlei3d(strategy);
  auto station = strategy.create("slei3d", stationContext(config));
  station->decide(stationView(0.0, {}));
  Report report;
  report.box = 0;
  report.remaining = 200.0;
  report.meetingNumber = 1;
  report.remainder = octreeChildren(kBoxes[0], 5.0);
  const auto reply =
      sent<Reply>(station->decide(stationView(60.0, {{"e1", kReportTopic, encode(report)}})), "e1",
                  kReplyTopic, decodeReply);
  ASSERT_TRUE(reply);
  EXPECT_EQ(reply->box, 0);
  EXPECT_FALSE(reply->boxShape);
}

// Four 10 m cubes in a row, A at x = 0 and B at 20 by the station, C at 100 and D at 120 far off.
const std::vector<agent::BoxView> kRow = {
    makeBox(Vec3(0, 0, 5), Vec3(10, 10, 10)), makeBox(Vec3(20, 0, 5), Vec3(10, 10, 10)),
    makeBox(Vec3(100, 0, 5), Vec3(10, 10, 10)), makeBox(Vec3(120, 0, 5), Vec3(10, 10, 10))};

std::optional<Reply> replyTo(agent::Strategy& station, const std::string& explorer, double time,
                             const Report& report,
                             const std::vector<agent::BoxView>* boxes = &kRow) {
  auto view = stationView(time, {{explorer, kReportTopic, encode(report)}}, boxes);
  view.odometry.position = Vec3(0, -15, 0.1);
  return sent<Reply>(station.decide(view), explorer, kReplyTopic, decodeReply);
}

Report reportOf(int32_t box, bool finished, uint32_t meetingNumber) {
  Report report;
  report.box = box;
  report.boxFinished = finished;
  report.remaining = 100.0;
  report.meetingNumber = meetingNumber;
  return report;
}

TEST(Slei3dStation, EachReplyReservesTheSubgroupsNextBox) {
  agent::StrategyRegistry registry;
  registerSlei3d(registry);
  const auto config = Config::fromText("", "run.ini");
  auto station = registry.create("slei3d", stationContext(config));
  auto first = stationView(0.0, {}, &kRow);
  first.odometry.position = Vec3(0, -15, 0.1);
  station->decide(first);  // the plan: e1 takes A (nearest the station), e2 then B
  // e1 reports A not done: it keeps A, and C (the free box nearest A) is reserved for it.
  const auto toE1 = replyTo(*station, "e1", 60.0, reportOf(0, false, 1));
  ASSERT_TRUE(toE1);
  EXPECT_EQ(toE1->box, 0);
  EXPECT_EQ(toE1->nextBox, 2);
  // e2 done with B: C is taken, so D; nothing is left to reserve.
  const auto toE2 = replyTo(*station, "e2", 70.0, reportOf(1, true, 1));
  ASSERT_TRUE(toE2);
  EXPECT_EQ(toE2->box, 3);
  EXPECT_EQ(toE2->nextBox, -1);
  // e1 went on to C by itself before its next meeting: C is its box now.
  const auto again = replyTo(*station, "e1", 160.0, reportOf(2, false, 2));
  ASSERT_TRUE(again);
  EXPECT_EQ(again->box, 2);
  EXPECT_EQ(again->nextBox, -1);

  // The paper's rule (off): no reservation, and e2 done with B gets C, the free box nearest B.
  const auto off = Config::fromText("[slei3d]\nreserve_next_box = false\n", "run.ini");
  auto plain = registry.create("slei3d", stationContext(off));
  plain->decide(first);
  EXPECT_EQ(replyTo(*plain, "e1", 60.0, reportOf(0, false, 1))->nextBox, -1);
  EXPECT_EQ(replyTo(*plain, "e2", 70.0, reportOf(1, true, 1))->box, 2);
  // slei-pre's fixed orders: the next box of its own list (e1: A, then C).
  auto pre = registry.create("slei-pre", stationContext(config));
  pre->decide(first);
  const auto fixed = replyTo(*pre, "e1", 60.0, reportOf(0, false, 1));
  ASSERT_TRUE(fixed);
  EXPECT_GE(fixed->nextBox, 2);
  EXPECT_EQ(replyTo(*pre, "e1", 120.0, reportOf(0, true, 2))->box, fixed->nextBox);
}

TEST(Slei3dStation, TheLastFreeBoxIsNotReservedWhileAnotherExplorerHasNone) {
  agent::StrategyRegistry registry;
  registerSlei3d(registry);
  const auto config = Config::fromText("", "run.ini");
  const std::vector<agent::BoxView> three(kRow.begin(), kRow.begin() + 3);  // A, B, C
  const auto planned = [&] {  // e1 takes A, e2 B; C is free
    auto station = registry.create("slei3d", stationContext(config));
    auto first = stationView(0.0, {}, &three);
    first.odometry.position = Vec3(0, -15, 0.1);
    station->decide(first);
    return station;
  };
  // e1 at work in A: C stays free, e2 (at work in B, nothing reserved) will ask for it ...
  auto station = planned();
  const auto toE1 = replyTo(*station, "e1", 60.0, reportOf(0, false, 1), &three);
  ASSERT_TRUE(toE1);
  EXPECT_EQ(toE1->box, 0);
  EXPECT_EQ(toE1->nextBox, -1);
  // ... and gets it when done with B.
  const auto toE2 = replyTo(*station, "e2", 70.0, reportOf(1, true, 1), &three);
  ASSERT_TRUE(toE2);
  EXPECT_EQ(toE2->box, 2);
  // e2 done with B asks first: C is its box; nothing is left to reserve for e1.
  auto other = planned();
  EXPECT_EQ(replyTo(*other, "e2", 50.0, reportOf(1, true, 1), &three)->box, 2);
  EXPECT_EQ(replyTo(*other, "e1", 60.0, reportOf(0, false, 1), &three)->nextBox, -1);
}

TEST(Slei3dStation, BadWorkspaceAndSearchKeysAreErrors) {
  agent::StrategyRegistry registry;
  registerSlei3d(registry);
  for (const auto& [text, key] : std::vector<std::pair<std::string, std::string>>{
           {"workspace = guess", "workspace"},
           {"leaf_edge = 0", "leaf_edge"},
           {"search_depth = 7", "search_depth"},
           {"search_depth = -1", "search_depth"},
           {"reserve_next_box = 2", "reserve_next_box"},
           {"frontier_chunk = 0.5", "frontier_chunk"},
           {"frontier_chunk = -1", "frontier_chunk"}}) {
    const auto config = Config::fromText("[slei3d]\n" + text + "\n", "bad.ini");
    const auto message =
        testing::messageOf([&] { registry.create("slei3d", stationContext(config)); });
    EXPECT_MENTIONS(message, "bad.ini");
    EXPECT_MENTIONS(message, key);
  }
}

}  // namespace
}  // namespace coinspect::strategies::slei
