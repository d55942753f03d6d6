// The slei3d ground station driven by hand: the unknown workspace's slabs and octree parts, the
// reserved next box (and the last free box kept for an explorer without one, or split while
// others work), work shared with an explorer left without a box.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
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

agent::StrategyContext stationContext(const Config& config, bool thirdExplorer = false) {
  std::vector<agent::FleetMember> fleet = {{"gcs", Role::GroundStation},
                                           {"e1", Role::Explorer},
                                           {"e2", Role::Explorer},
                                           {"p1", Role::Photographer},
                                           {"p2", Role::Photographer}};
  if (thirdExplorer) fleet.push_back({"e3", Role::Explorer});
  return agent::StrategyContext{config, "slei3d", "gcs", Role::GroundStation, 0, 1, fleet, {}, 0.0};
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

TEST(Slei3dStation, AReportWithoutABoxButWithPartsSplitsNothing) {
  // Not what an explorer sends (without a box it reports it finished), but it decodes: the
  // station must not look the box up.
  const auto config = Config::fromText("[slei3d]\nworkspace = unknown\n", "run.ini");
  auto strategy = agent::StrategyRegistry{};
  registerSlei3d(strategy);
  auto station = strategy.create("slei3d", stationContext(config));
  station->decide(stationView(0.0, {}));
  Report report;
  report.box = -1;
  report.remaining = 200.0;
  report.meetingNumber = 1;
  report.remainder = octreeChildren(kBoxes[0], 5.0);
  const auto reply =
      sent<Reply>(station->decide(stationView(60.0, {{"e1", kReportTopic, encode(report)}})), "e1",
                  kReplyTopic, decodeReply);
  ASSERT_TRUE(reply);
  EXPECT_EQ(reply->box, -1);
  EXPECT_FALSE(reply->boxShape);
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

// An explorer without a box whose inspectors have nothing left.
Report boxlessReport(uint32_t meetingNumber) {
  Report report = reportOf(-1, true, meetingNumber);
  report.remaining = 0.0;
  return report;
}

// A `method` station at (0, -15) after its first decision, the plan over `boxes`: e1 takes A
// (nearest the station), e2 then B.
std::unique_ptr<agent::Strategy> plannedStation(const std::string& configText,
                                                const std::vector<agent::BoxView>* boxes = &kRow,
                                                const std::string& method = "slei3d",
                                                bool thirdExplorer = false) {
  agent::StrategyRegistry registry;
  registerSlei3d(registry);
  auto station = registry.create(
      method, stationContext(Config::fromText(configText, "run.ini"), thirdExplorer));
  auto first = stationView(0.0, {}, boxes);
  first.odometry.position = Vec3(0, -15, 0.1);
  station->decide(first);
  return station;
}

TEST(Slei3dStation, EachReplyReservesTheSubgroupsNextBox) {
  auto station = plannedStation("");
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
  auto plain = plannedStation("[slei3d]\nreserve_next_box = false\n");
  EXPECT_EQ(replyTo(*plain, "e1", 60.0, reportOf(0, false, 1))->nextBox, -1);
  EXPECT_EQ(replyTo(*plain, "e2", 70.0, reportOf(1, true, 1))->box, 2);
  // slei-pre's fixed orders: the next box of its own list (e1: A, then C).
  auto pre = plannedStation("", &kRow, "slei-pre");
  const auto fixed = replyTo(*pre, "e1", 60.0, reportOf(0, false, 1));
  ASSERT_TRUE(fixed);
  EXPECT_GE(fixed->nextBox, 2);
  EXPECT_EQ(replyTo(*pre, "e1", 120.0, reportOf(0, true, 2))->box, fixed->nextBox);
}

TEST(Slei3dStation, TheLastFreeBoxIsNotReservedWhileAnotherExplorerHasNone) {
  const std::vector<agent::BoxView> three(kRow.begin(), kRow.begin() + 3);  // A, B, C: C free
  // e1 at work in A: C stays free, e2 (at work in B, nothing reserved) will ask for it ...
  auto station = plannedStation("", &three);
  const auto toE1 = replyTo(*station, "e1", 60.0, reportOf(0, false, 1), &three);
  ASSERT_TRUE(toE1);
  EXPECT_EQ(toE1->box, 0);
  EXPECT_EQ(toE1->nextBox, -1);
  // ... and gets it when done with B.
  const auto toE2 = replyTo(*station, "e2", 70.0, reportOf(1, true, 1), &three);
  ASSERT_TRUE(toE2);
  EXPECT_EQ(toE2->box, 2);
  // e2 done with B asks first: C is its box; nothing is left to reserve for e1.
  auto other = plannedStation("", &three);
  EXPECT_EQ(replyTo(*other, "e2", 50.0, reportOf(1, true, 1), &three)->box, 2);
  EXPECT_EQ(replyTo(*other, "e1", 60.0, reportOf(0, false, 1), &three)->nextBox, -1);
}

TEST(Slei3dStation, TheLastFreeBoxIsSplitAcrossItsFootprintWhileAnotherExplorerWorks) {
  // A and B by the station, C a 20 x 20 m box far off: the last free one.
  const std::vector<agent::BoxView> boxes = {kRow[0], kRow[1],
                                             makeBox(Vec3(110, 0, 5), Vec3(20, 20, 10))};
  auto station = plannedStation("[slei3d]\nsplit_last_box = true\n", &boxes);
  // e2 done with B while e1 still works in A: C is split in two across x (one part per
  // explorer), and e2 gets the half nearest B, a part whose shape it is sent (the full height).
  const auto toE2 = replyTo(*station, "e2", 70.0, reportOf(1, true, 1), &boxes);
  ASSERT_TRUE(toE2 && toE2->boxShape);
  EXPECT_GE(toE2->box, 3);
  EXPECT_TRUE(toE2->boxShape->size.isApprox(Vec3(10, 20, 10), 1e-9));
  EXPECT_TRUE(toE2->boxShape->center.isApprox(Vec3(105, 0, 5), 1e-9));
  // e1, done with A, gets the other half at once, whole (a part is not split again), without
  // waiting for a share of e2's.
  const auto toE1 = replyTo(*station, "e1", 80.0, reportOf(0, true, 1), &boxes);
  ASSERT_TRUE(toE1 && toE1->boxShape);
  EXPECT_EQ(toE1->box, toE2->box == 3 ? 4 : 3);
  EXPECT_TRUE(toE1->boxShape->center.isApprox(Vec3(115, 0, 5), 1e-9));

  // Off (the default): e2 gets C whole, and e1 done with A has nothing left but to wait for a
  // share of it.
  auto whole = plannedStation("", &boxes);
  const auto all = replyTo(*whole, "e2", 70.0, reportOf(1, true, 1), &boxes);
  ASSERT_TRUE(all);
  EXPECT_EQ(all->box, 2);
  EXPECT_FALSE(all->boxShape);
  EXPECT_EQ(replyTo(*whole, "e1", 80.0, reportOf(0, true, 1), &boxes)->box, -1);

  // Three explorers (e3 in the 10 m box at x = 100): C's four 10 m columns.
  const std::vector<agent::BoxView> four = {kRow[0], kRow[1], kRow[2],
                                            makeBox(Vec3(130, 0, 5), Vec3(20, 20, 10))};
  auto three = plannedStation("[slei3d]\nsplit_last_box = true\n", &four, "slei3d", true);
  const auto column = replyTo(*three, "e2", 70.0, reportOf(1, true, 1), &four);
  ASSERT_TRUE(column && column->boxShape);
  EXPECT_GE(column->box, 4);
  EXPECT_TRUE(column->boxShape->size.isApprox(Vec3(10, 10, 10), 1e-9));
}

TEST(Slei3dStation, AnExplorerWithoutABoxGetsTheReservedBoxOfOneAtWork) {
  auto station = plannedStation("");
  const auto toE1 = replyTo(*station, "e1", 60.0, reportOf(0, false, 1));  // C reserved for e1
  ASSERT_TRUE(toE1);
  EXPECT_EQ(toE1->nextBox, 2);
  EXPECT_EQ(replyTo(*station, "e2", 70.0, reportOf(1, true, 1))->box, 3);  // D
  // e2 done with D, none free: it is to wait beside e1's next meeting, just after it.
  const auto waiting = replyTo(*station, "e2", 150.0, reportOf(3, true, 2));
  ASSERT_TRUE(waiting);
  EXPECT_EQ(waiting->box, -1);
  EXPECT_DOUBLE_EQ(waiting->next.time, toE1->next.time + 10.0);
  EXPECT_NEAR((waiting->next.place - toE1->next.place).norm(), 2.5, 1e-9);
  // There, before its time, it is not answered; e1, still in A, gives C back ...
  EXPECT_FALSE(replyTo(*station, "e2", toE1->next.time - 5.0, boxlessReport(3)));
  const auto kept = replyTo(*station, "e1", toE1->next.time, reportOf(0, false, 2));
  ASSERT_TRUE(kept);
  EXPECT_EQ(kept->box, 0);
  EXPECT_EQ(kept->nextBox, -1);
  // ... which e2 gets at its time.
  const auto shared = replyTo(*station, "e2", waiting->next.time, boxlessReport(3));
  ASSERT_TRUE(shared);
  EXPECT_EQ(shared->box, 2);
  EXPECT_DOUBLE_EQ(shared->next.time, waiting->next.time + 60.0);  // a new box's first meeting
  EXPECT_FALSE(shared->boxShape);  // a box of the scene: the explorers know it
}

TEST(Slei3dStation, WithNoBoxFreeTheBoxOfOneAtWorkIsSplitForOneWithout) {
  const std::vector<agent::BoxView> two(kRow.begin(), kRow.begin() + 2);  // A, B: none free
  Report atWork = reportOf(0, false, 1);
  atWork.remainder = octreeChildren(two[0], 4.0, false);  // A's four columns, all with work
  ASSERT_EQ(atWork.remainder.size(), 4u);
  auto station = plannedStation("", &two);
  const auto toE1 = replyTo(*station, "e1", 60.0, atWork, &two);  // no one waits: kept whole
  ASSERT_TRUE(toE1);
  EXPECT_EQ(toE1->box, 0);
  const auto waiting = replyTo(*station, "e2", 70.0, reportOf(1, true, 1), &two);
  ASSERT_TRUE(waiting);
  EXPECT_EQ(waiting->box, -1);
  // At e1's next meeting A is split: e1 goes on with one of its columns, a part whose shape it
  // is sent (the full height of A); e2 gets another at its time.
  atWork.meetingNumber = 2;
  const auto part = replyTo(*station, "e1", toE1->next.time, atWork, &two);
  ASSERT_TRUE(part && part->boxShape);
  EXPECT_GE(part->box, 2);
  EXPECT_TRUE(part->boxShape->size.isApprox(Vec3(5, 5, 10), 1e-9));
  const auto share = replyTo(*station, "e2", waiting->next.time, boxlessReport(2), &two);
  ASSERT_TRUE(share && share->boxShape);
  EXPECT_GE(share->box, 2);
  EXPECT_NE(share->box, part->box);
  EXPECT_DOUBLE_EQ(share->next.time, waiting->next.time + 60.0);
  EXPECT_FALSE(sameBox(*share->boxShape, *part->boxShape));

  // share_work off: e2 is done, and A stays whole.
  auto alone = plannedStation("[slei3d]\nshare_work = false\n", &two);
  atWork.meetingNumber = 1;
  ASSERT_TRUE(replyTo(*alone, "e1", 60.0, atWork, &two));
  EXPECT_EQ(replyTo(*alone, "e2", 70.0, reportOf(1, true, 1), &two)->box, -1);
  atWork.meetingNumber = 2;
  EXPECT_EQ(replyTo(*alone, "e1", toE1->next.time, atWork, &two)->box, 0);

  // explore-then-inspect shares no work unless told to: an explorer without a box is done (it
  // then hands out what it found) rather than sent to wait beside e1's next meeting.
  for (const bool share : {false, true}) {
    auto eti =
        plannedStation(share ? "[slei3d]\nshare_work = true\n" : "", &two, "explore-then-inspect");
    atWork.meetingNumber = 1;
    const auto e1 = replyTo(*eti, "e1", 60.0, atWork, &two);
    ASSERT_TRUE(e1);
    const auto e2 = replyTo(*eti, "e2", 70.0, reportOf(1, true, 1), &two);
    ASSERT_TRUE(e2);
    EXPECT_EQ(e2->box, -1);
    EXPECT_EQ(std::abs((e2->next.place - e1->next.place).norm() - 2.5) < 1e-9, share) << share;
  }
}

// `feasible_meetings`: e1 (box A, by the station) is due at A's corner at 160 s; e2 then reports
// from D, 120 m off, and eq. 9 would have it met at 161 s, which the station at 1 m/s can keep
// only by leaving e1 waiting. With the option e2's meeting is put where the station's route gets
// there after e1's (about 170 s + 112 m), and e1's stays as it was.
TEST(Slei3dStation, WithFeasibleMeetingsTheStationPromisesOnlyWhatItsRouteKeeps) {
  for (const bool feasible : {false, true}) {
    auto station = plannedStation(feasible ? "[slei3d]\nfeasible_meetings = true\n" : "");
    const auto toE1 = replyTo(*station, "e1", 60.0, reportOf(0, false, 1));
    ASSERT_TRUE(toE1);
    EXPECT_DOUBLE_EQ(toE1->next.time, 160.0);  // eq. 9's 100 s: the station is free for it
    const auto toE2 = replyTo(*station, "e2", 61.0, reportOf(3, false, 1));
    ASSERT_TRUE(toE2);
    ASSERT_EQ(toE2->box, 3);
    const double drive = std::hypot(toE2->next.place.x() - toE1->next.place.x(),
                                    toE2->next.place.y() - toE1->next.place.y());
    EXPECT_GT(drive, 100.0);
    if (!feasible) {
      EXPECT_DOUBLE_EQ(toE2->next.time, 161.0);
      continue;
    }
    // The first 10 s step at or after the arrival that keeps e1 on time.
    const double arrival = 160.0 + kMeetingService + drive;
    EXPECT_GE(toE2->next.time + 10.0, arrival);  // within the grace of the arrival
    EXPECT_LT(toE2->next.time, arrival);
    // The station's stops sent to e2: e1's meeting first, at its time.
    ASSERT_EQ(toE2->stops.size(), 2U);
    EXPECT_DOUBLE_EQ(toE2->stops[0].time, 160.0);
  }
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
           {"feasible_meetings = maybe", "feasible_meetings"},
           {"share_work = often", "share_work"},
           {"frontier_chunk = 0.5", "frontier_chunk"},
           {"frontier_chunk = -1", "frontier_chunk"}}) {
    const auto config = Config::fromText("[slei3d]\n" + text + "\n", "bad.ini");
    const auto message =
        testing::messageOf([&] { registry.create("slei3d", stationContext(config)); });
    EXPECT_MENTIONS(message, "bad.ini");
    EXPECT_MENTIONS(message, key);
  }
}

// The static station's meetings: slei-fix's every fix_interval (120 s), caric-team's at most
// every team_interval (300 s), where the station stands, the first ones too.
TEST(Slei3dStation, AStaticStationMeetsEveryIntervalOfItsVariant) {
  const auto nextMeetings = [](const std::string& variant, const std::string& text) {
    const auto config = Config::fromText(text, "run.ini");
    auto strategy = agent::StrategyRegistry{};
    registerSlei3d(strategy);
    auto station = strategy.create(variant, stationContext(config));
    std::optional<FleetPlan> plan;
    for (const auto& m : station->decide(stationView(0.0, {})).messages)
      if (m.topic == kPlanTopic) plan = decodePlan(m.bytes);
    EXPECT_TRUE(plan && !plan->subgroups.empty());
    const double first = plan ? plan->subgroups.front().firstMeeting.time : -1.0;
    const auto reply = sent<Reply>(
        station->decide(stationView(50.0, {{"e1", kReportTopic, encode(reportOf(0, false, 1))}})),
        "e1", kReplyTopic, decodeReply);
    EXPECT_TRUE(reply);
    if (reply) {
      EXPECT_TRUE(reply->next.place.isApprox(Vec3(15, -15, 0.1), 1e-9));
    }
    return std::make_pair(first, reply ? reply->next.time : -1.0);
  };
  EXPECT_EQ(nextMeetings("slei-fix", ""), std::make_pair(120.0, 170.0));
  EXPECT_EQ(nextMeetings("caric-team", ""), std::make_pair(300.0, 350.0));
  EXPECT_EQ(nextMeetings("caric-team", "[slei3d]\nteam_interval = 200\n"),
            std::make_pair(200.0, 250.0));
  EXPECT_EQ(nextMeetings("slei-fix", "[slei3d]\nteam_interval = 200\n"),
            std::make_pair(120.0, 170.0));
  EXPECT_THROW(nextMeetings("caric-team", "[slei3d]\nteam_interval = 5\n"), InputError);
}

}  // namespace
}  // namespace coinspect::strategies::slei
