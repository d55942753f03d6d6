// The slei3d explorer driven by hand on a perfect vehicle: with its next box reserved, an
// explorer done with its box goes on to the next one before its station meeting; without one, it
// looks for a late station along the station's route, never past the time to leave for its own
// meeting; before it is done with a box, it flies over it (the roof pass); it comes back for an
// inspector's results until its list is done, and not once it is done, inspected or skipped, and
// with no box left not even for its station meeting; with `fetch_detour` and no next box
// reserved, it fetches done results on its way to the station; pushed off its station meeting
// point, it goes back; with `handout_at_box_end` it hands out nothing before its box is
// explored, and never a feature whose result it carries; caric-team's explorer splits its
// features among its free inspectors at the hub, hands out there on each return before it goes
// on to its box, comes back there once its last box is explored (its first one too, before any
// reply), and waits on its own side of the station.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "coinspect/strategies/slei/fleet_plan.h"
#include "coinspect/strategies/slei/protocol.h"
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
  double highest = 0.0;               // m, over the whole run
  // m, horizontal, from box 0's footprint corners nearest to and farthest from the start, at
  // least 1 m above the box.
  double closestOverNearCorner = 1e300, closestOverFarCorner = 1e300;
  // m/s, the slowest setpoint within 0.5 m of that near corner (over it, as above).
  double slowestOverNearCorner = 1e300;
};

Vec3 cornerOf(size_t box) {
  return boxCorner(kBoxes, box, 2.0, 0.0, Vec3(0, 0, 0));
}

// Explorer "e1" (fleet index 1) of `strategy`, with the other units `fleet` names.
std::unique_ptr<agent::Strategy> makeExplorer(const Config& config, const char* strategy,
                                              std::vector<agent::FleetMember> fleet) {
  static agent::StrategyRegistry registry = [] {
    agent::StrategyRegistry r;
    registerSlei3d(r);
    return r;
  }();
  return registry.create(
      strategy, agent::StrategyContext{
                    config, strategy, "e1", Role::Explorer, 1, 1, std::move(fleet), {}, 0.5});
}

// e1 alive on the ground at the origin, seeing the boxes.
agent::AgentView startView() {
  agent::AgentView view;
  view.name = "e1";
  view.role = Role::Explorer;
  view.alive = true;
  view.boxes = &kBoxes;
  view.odometry.position = Vec3(0, 0, 0.1);
  return view;
}

// The station's first reply to e1: box 0 kept, `nextBox` reserved after it (-1: none), the next
// meeting at box 0's corner at `meetingTime`, after the station's stops `before`.
Reply keepBox0(int32_t nextBox, double meetingTime, std::vector<Meeting> before = {}) {
  Reply reply;
  reply.meetingNumber = 1;
  reply.box = 0;
  reply.next = {cornerOf(0), meetingTime};
  reply.stops = std::move(before);
  reply.stops.push_back(reply.next);
  reply.nextBox = nextBox;
  return reply;
}

// e1 explores box 0; its meeting with the station (never in range) is at `meetingTime` at box
// 0's corner; a reply at 1 s (as if met on the way) optionally reserves box 1, and lists the
// station's stops before that meeting (`before`).
Run fly(const Config& config, int32_t reserved, double until, std::vector<Meeting> before = {},
        double meetingTime = 400.0) {
  Run run;
  run.explorer =
      makeExplorer(config, "slei3d", {{"gcs", Role::GroundStation}, {"e1", Role::Explorer}});
  const Vec3 corner = cornerOf(0);
  FleetPlan plan;
  plan.subgroups.push_back({1, {}, 0, {corner, meetingTime}, 0});
  const Reply reply = keepBox0(reserved, meetingTime, std::move(before));
  run.view = startView();
  auto& view = run.view;
  for (int step = 0; step * 0.1 <= until; ++step) {
    view.time = step * 0.1;
    view.messages.clear();
    if (step == 0) view.messages.push_back({"gcs", kPlanTopic, encode(plan)});
    if (step == 10) view.messages.push_back({"gcs", kReplyTopic, encode(reply)});
    const auto command = run.explorer->decide(view);
    if (command.setpoint) view.odometry.position = command.setpoint->position;
    const Vec3& at = view.odometry.position;
    run.closestToSecondBox =
        std::min(run.closestToSecondBox, (at - kBoxes[1].center).head<2>().norm());
    run.highest = std::max(run.highest, at.z());
    if (at.z() > 5.0) {
      const double fromNearCorner = (at.head<2>() - Eigen::Vector2d(-2, 8)).norm();
      run.closestOverNearCorner = std::min(run.closestOverNearCorner, fromNearCorner);
      if (fromNearCorner < 0.5 && command.setpoint)
        run.slowestOverNearCorner =
            std::min(run.slowestOverNearCorner, command.setpoint->velocity.norm());
      run.closestOverFarCorner =
          std::min(run.closestOverFarCorner, (at.head<2>() - Eigen::Vector2d(2, 12)).norm());
    }
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

// Looking for the station along its route never costs it its own meeting, where the station
// comes and gives it up a while after. Its meeting at `m` s at box 0's corner; the station's
// route: a stop 10 m south of the start at 20 s (too soon for it), then box 1's corner (40 m
// east) at m - 25 s, where it would find the station at about 70 s. With m = 150 s it waits
// there, and leaves in time for its own meeting (before: it waited its whole patience there and
// went on to the stop before: 40 m off at 150 s). With m = 130 s it could not wait its patience
// there and be back in time: it does not go.
TEST(Slei3dExplorer, LookingForTheStationItKeepsItsOwnMeeting) {
  const auto config = Config::fromText("", "run.ini");
  const auto route = [](double m) {
    return std::vector<Meeting>{{Vec3(0, -10, 0), 20.0}, {cornerOf(1), m - 25.0}};
  };
  const auto fromOwnPlace = [](const slei::Run& run) {
    return (run.view.odometry.position - cornerOf(0)).head<2>().norm();
  };
  const auto waits = fly(config, -1, 150.0, route(150.0), 150.0);
  EXPECT_LT(waits.closestToSecondBox, 8.0);
  EXPECT_LT(fromOwnPlace(waits), 2.0);
  const auto stays = fly(config, -1, 130.0, route(130.0), 130.0);
  EXPECT_GT(stays.closestToSecondBox, 30.0);
  EXPECT_LT(fromOwnPlace(stays), 2.0);
}

// Its box swept (here: nothing mapped to sweep), it flies over it from the footprint's corner
// nearest where it came from to the opposite one, above the space kept blocked over the box
// while unknown (box top 4 m + 1 m): its LiDAR then sees the roofs from above. Without the roof
// pass it never rises above its entry height (3 m).
TEST(Slei3dExplorer, BeforeItsBoxIsDoneItFliesOverItCornerToCorner) {
  const auto pass = fly(Config::fromText("", "run.ini"), -1, 60.0);
  EXPECT_GT(pass.highest, 6.0);
  EXPECT_LT(pass.closestOverNearCorner, 0.5);
  EXPECT_LT(pass.closestOverFarCorner, 0.5);
  const auto none = fly(Config::fromText("[slei3d]\nroof_pass = false\n", "run.ini"), -1, 60.0);
  EXPECT_LT(none.highest, 3.5);
}

// The roof pass's two corners are two stops of its sweep: it flies through the near corner at
// the turn's speed (`sweep_through`); one stop at a time it brakes to a halt over it.
TEST(Slei3dExplorer, WithSweepThroughItPassesAStopWithoutHalting) {
  const auto through = fly(Config::fromText("", "run.ini"), -1, 60.0);
  const auto stops =
      fly(Config::fromText("[slei3d]\nsweep_through = false\n", "run.ini"), -1, 60.0);
  ASSERT_LT(stops.closestOverNearCorner, 0.5);
  ASSERT_LT(through.closestOverNearCorner, 0.5);
  EXPECT_LT(through.closestOverFarCorner, 0.5);
  EXPECT_LT(stops.slowestOverNearCorner, 0.05);
  EXPECT_GT(through.slowestOverNearCorner, 0.3);
}

// The sequence numbers of the orders e1 (slei3d) sends i1 (its one inspector, always in sight)
// while, with no box left, it hands out one feature and then comes to take i1's results. i1 answers
// every new orders with its status, and says it again every second (as an inspector does while
// its explorer is near): the feature still on its list, or from orders number `doneFrom` on,
// its list done, the feature inspected (or, `skipped`, not). With `meeting`, the reply names it
// as the next station meeting, and as the station's one stop; by default there is none.
struct Collection {
  std::vector<uint32_t> sent;  // sequence numbers
  double lastOrdersAt = -1.0;  // s, when e1 last sent orders
  Vec3 at = Vec3::Zero();      // where e1 is at `until`
};

Collection handOutAndCollect(uint32_t doneFrom, double until, bool skipped = false,
                             std::optional<Meeting> meeting = std::nullopt) {
  auto explorer = makeExplorer(
      Config::fromText("", "run.ini"), "slei3d",
      {{"gcs", Role::GroundStation}, {"e1", Role::Explorer}, {"i1", Role::Photographer}});
  FleetPlan plan;
  plan.subgroups.push_back({1, {2}, 0, {cornerOf(0), 400.0}, 0});
  Reply reply;  // at 1 s: no box left, no meeting
  reply.meetingNumber = 1;
  reply.box = -1;
  reply.next = {cornerOf(0), 1e300};
  if (meeting) {
    reply.next = *meeting;
    reply.stops = {*meeting};
  }
  agent::AgentView view = startView();
  agent::NeighbourInfo inspector{"i1", Role::Photographer, {}};
  inspector.odometry.position = Vec3(-6, 4, 3);
  Collection run;
  auto& sent = run.sent;
  std::vector<agent::ReceivedMessage> answers;
  std::optional<Status> said;
  for (int step = 0; step * 0.1 <= until; ++step) {
    view.time = step * 0.1;
    view.messages = std::move(answers);
    answers.clear();
    if (said && step % 10 == 0)
      view.messages.push_back({"i1", kStatusTopic, encode(*said), view.time});
    view.neighbours = {inspector};
    view.detectedFeatures.clear();
    if (step == 0) view.messages.push_back({"gcs", kPlanTopic, encode(plan)});
    if (step == 10) view.messages.push_back({"gcs", kReplyTopic, encode(reply)});
    if (step == 20) view.detectedFeatures.push_back({7, Vec3(0, 8, 2), -Vec3::UnitY(), 2.0});
    const auto command = explorer->decide(view);
    if (command.setpoint) view.odometry.position = command.setpoint->position;
    for (const auto& message : command.messages) {
      if (message.to != "i1" || message.topic != kOrdersTopic) continue;
      run.lastOrdersAt = view.time;
      const auto orders = decodeOrders(message.bytes);
      if (!orders || (!sent.empty() && sent.back() == orders->sequence)) continue;
      sent.push_back(orders->sequence);
      Status status;
      status.lastOrders = orders->sequence;
      const bool done = orders->sequence >= doneFrom;
      if (done && !skipped) status.inspected = {7};
      status.listLeft = done ? 0 : 1;
      answers.push_back({"i1", kStatusTopic, encode(status), view.time});
      said = status;
    }
  }
  run.at = view.odometry.position;
  return run;
}

std::vector<uint32_t> ordersToInspector(uint32_t doneFrom, double until, bool skipped = false) {
  return handOutAndCollect(doneFrom, until, skipped).sent;
}

// An inspector met for its results while still at its list is met again (its last results
// stayed with it when the explorer took it for done, and the station let the explorer go with
// nothing outstanding); once it reports the feature inspected and its list done, it is not.
TEST(Slei3dExplorer, ItComesBackForTheResultsOfAnInspectorStillAtItsList) {
  const auto late = ordersToInspector(1000, 120.0);
  ASSERT_GE(late.size(), 3u);  // the hand-out, then two collections at least
  EXPECT_EQ(late[2], 3u);
  // Done by the first collection: the hand-out and that one.
  EXPECT_EQ(ordersToInspector(2, 120.0), (std::vector<uint32_t>{1, 2}));
}

// With no box left, e1 goes on collecting i1's results (i1 never done) past the time to leave
// for its station meeting at 60 s at box 1's corner (about 33 s of flight from where it meets
// i1, so about 27 s), until 30 s past the meeting less the flight there (about 57 s); then it
// flies there. Before, it left at the time to leave and never came back for them (slei-a: 5
// inspected results that never reached the station).
TEST(Slei3dExplorer, WithNoBoxLeftItCollectsPastTheTimeToLeaveForItsMeeting) {
  const auto run = handOutAndCollect(1000, 130.0, false, Meeting{cornerOf(1), 60.0});
  EXPECT_GT(run.lastOrdersAt, 50.0);
  EXPECT_LT(run.lastOrdersAt, 60.0);
  EXPECT_LT((run.at - cornerOf(1)).head<2>().norm(), 5.0);
}

// e1 explores box 0 (meeting at 400 s by the box, no next box reserved) and hands the feature
// found at 2 s to i1 (always in link), which acknowledges it and inspects it on its own time
// (it never says it is done). At 50 s a second reply (as if the station passed by) sets the
// next meeting 40 m away at box 1's corner at 95 s. When e1 sent i1 orders again (sequence 2:
// a collection) and when it got to the meeting point.
struct Fetch {
  double collectedAt = -1.0;
  double arrivedAt = -1.0;
};

Fetch fetchBeforeMeeting(const Config& config) {
  auto explorer = makeExplorer(
      config, "slei3d",
      {{"gcs", Role::GroundStation}, {"e1", Role::Explorer}, {"i1", Role::Photographer}});
  FleetPlan plan;
  plan.subgroups.push_back({1, {2}, 0, {cornerOf(0), 400.0}, 0});
  Reply moved = keepBox0(-1, 95.0);
  moved.meetingNumber = 2;
  moved.next.place = cornerOf(1);
  moved.stops = {moved.next};
  agent::AgentView view = startView();
  agent::NeighbourInfo inspector{"i1", Role::Photographer, {}};
  inspector.odometry.position = Vec3(-6, 4, 3);
  Fetch run;
  std::vector<agent::ReceivedMessage> answers;
  for (int step = 0; step * 0.1 <= 110.0; ++step) {
    view.time = step * 0.1;
    view.messages = std::move(answers);
    answers.clear();
    view.neighbours = {inspector};
    view.detectedFeatures.clear();
    if (step == 0) view.messages.push_back({"gcs", kPlanTopic, encode(plan)});
    if (step == 10) view.messages.push_back({"gcs", kReplyTopic, encode(keepBox0(-1, 400.0))});
    if (step == 500) view.messages.push_back({"gcs", kReplyTopic, encode(moved)});
    if (step == 20) view.detectedFeatures.push_back({7, Vec3(0, 8, 2), -Vec3::UnitY(), 2.0});
    const auto command = explorer->decide(view);
    if (command.setpoint) view.odometry.position = command.setpoint->position;
    if (run.arrivedAt < 0.0 && (view.odometry.position - cornerOf(1)).head<2>().norm() < 5.0)
      run.arrivedAt = view.time;
    for (const auto& message : command.messages) {
      if (message.to != "i1" || message.topic != kOrdersTopic) continue;
      const auto orders = decodeOrders(message.bytes);
      if (!orders) continue;
      if (orders->sequence == 2 && run.collectedAt < 0.0) run.collectedAt = view.time;
      Status status;
      status.lastOrders = orders->sequence;
      status.listLeft = 1;
      answers.push_back({"i1", kStatusTopic, encode(status), view.time});
    }
  }
  return run;
}

// With `fetch_detour`, e1 meets i1 for its results on the way to its station meeting (i1's list
// of one feature should be done by then) and is at the meeting in time; without, it flies
// straight there.
TEST(Slei3dExplorer, WithNoNextBoxItFetchesDoneResultsOnItsWayToTheStation) {
  const auto off = fetchBeforeMeeting(Config::fromText("", "run.ini"));
  const auto on = fetchBeforeMeeting(Config::fromText("[slei3d]\nfetch_detour = 30\n", "run.ini"));
  EXPECT_LT(off.collectedAt, 0.0);
  ASSERT_GT(on.collectedAt, 50.0);  // after the reply that set the meeting
  ASSERT_GT(on.arrivedAt, 0.0);
  EXPECT_LT(on.collectedAt, on.arrivedAt);
  EXPECT_LE(on.arrivedAt, 95.0);
}

// e1 (its box explored at once: nothing is scanned) waits at its point for the station's meeting
// due at 40 s at (20, 4) (never in link); from 60 s to 70 s e0, of higher priority, hovers 1 m from
// it and pushes it away. Once the meeting is due, a unit pushed off its point flies back to it
// (before, it held where it had backed off to for good: on slei-c an explorer 5.05 m from the
// waiting station).
TEST(Slei3dExplorer, PushedOffItsStationMeetingPointItGoesBack) {
  const auto config = Config::fromText("", "run.ini");
  auto explorer =
      makeExplorer(config, "slei3d",
                   {{"e0", Role::Explorer}, {"e1", Role::Explorer}, {"gcs", Role::GroundStation}});
  FleetPlan plan;
  plan.subgroups.push_back({1, {}, 0, {Vec3(20, 4, 0), 40.0}, 2});
  agent::AgentView view = startView();
  Vec3 point = Vec3::Zero(), pushedTo = Vec3::Zero();
  for (int step = 0; step * 0.1 <= 100.0; ++step) {
    view.time = step * 0.1;
    view.messages.clear();
    if (step == 0) view.messages.push_back({"gcs", kPlanTopic, encode(plan)});
    view.neighbours.clear();
    if (view.time >= 60.0 && view.time < 70.0) {
      agent::NeighbourInfo pusher{"e0", Role::Explorer, {}};
      pusher.odometry.position = point + Vec3(1, 0, 0);
      view.neighbours.push_back(pusher);
    }
    const auto command = explorer->decide(view);
    if (command.setpoint) view.odometry.position = command.setpoint->position;
    if (step == 590) point = view.odometry.position;
    if (step == 699) pushedTo = view.odometry.position;
  }
  EXPECT_LT((point - Vec3(20, 4, 0)).head<2>().norm(), 4.5);  // it was at its point
  EXPECT_GT((pushedTo - point).norm(), 2.0);                  // e0 pushed it away
  EXPECT_LT((view.odometry.position - point).norm(), 0.5);    // back at its point
}

// An inspector that reports its list done without the feature (it skipped it) is free: e1 does
// not come back for results it will never have. (Kept on its list, the feature had it busy for
// good in e1's plans, and caric-team's explorers waited for it to be free before handing out.)
TEST(Slei3dExplorer, AnInspectorDoneWithItsListIsFreeEvenWithAFeatureSkipped) {
  EXPECT_EQ(ordersToInspector(1, 120.0), (std::vector<uint32_t>{1}));
  EXPECT_EQ(ordersToInspector(1, 120.0, true), (std::vector<uint32_t>{1}));
}

// A caric-team e1 (with inspector i1) whose first box is box 1, its first meeting at the hub
// (box 0's corner) at 400 s, flown up to 250 s or until it is back at the hub having been at
// box 1 (explored at once: nothing is scanned); `reply` arrives at 1 s, and with `found` a
// feature is found at 2 s.
struct HubReturn {
  double nearestBox1 = 1e300;  // m, horizontal
  double backAt = -1.0;        // s, -1: not back by 250 s
};
HubReturn flyCaricTeamBox1(const std::optional<Reply>& reply, bool found) {
  auto explorer = makeExplorer(
      Config::fromText("", "run.ini"), "caric-team",
      {{"gcs", Role::GroundStation}, {"e1", Role::Explorer}, {"i1", Role::Photographer}});
  FleetPlan plan;
  plan.subgroups.push_back({1, {2}, 1, {cornerOf(0), 400.0}, 0});
  agent::AgentView view = startView();
  HubReturn run;
  for (int step = 0; step * 0.1 <= 250.0 && run.backAt < 0.0; ++step) {
    view.time = step * 0.1;
    view.messages.clear();
    view.detectedFeatures.clear();
    if (step == 0) view.messages.push_back({"gcs", kPlanTopic, encode(plan)});
    if (step == 10 && reply) view.messages.push_back({"gcs", kReplyTopic, encode(*reply)});
    if (step == 20 && found)
      view.detectedFeatures.push_back({7, Vec3(20, 4, 2), -Vec3::UnitY(), 2.0});
    const auto command = explorer->decide(view);
    if (command.setpoint) view.odometry.position = command.setpoint->position;
    const Vec3& at = view.odometry.position;
    run.nearestBox1 = std::min(run.nearestBox1, (at - kBoxes[1].center).head<2>().norm());
    if (run.nearestBox1 < 8.0 && (at - cornerOf(0)).head<2>().norm() < 5.0) run.backAt = view.time;
  }
  return run;
}

// caric-team hands out only at its hub: with box 1 explored and a feature found on the way, it
// flies back there long before its meeting at 400 s. (It waited at the box for the meeting
// before.)
TEST(Slei3dExplorer, CaricTeamDoneWithItsLastBoxGoesToItsHubWithWhatItFound) {
  Reply reply;  // as if met on the way: box 1 still, the station's one stop the hub
  reply.meetingNumber = 1;
  reply.box = 1;
  reply.next = {cornerOf(0), 400.0};
  reply.stops = {reply.next};
  const HubReturn run = flyCaricTeamBox1(reply, true);
  EXPECT_LT(run.nearestBox1, 8.0);  // it went to box 1
  EXPECT_GT(run.backAt, 0.0);       // and came back to the hub
  EXPECT_LT(run.backAt, 250.0);
}

// Before any reply it knows none of the station's stops: done with its first box, it still
// comes back to the static station at once, not at its meeting's time (it hovered by the box
// until then: earlyStop).
TEST(Slei3dExplorer, CaricTeamDoneWithItsFirstBoxBeforeAnyReplyGoesToTheHub) {
  const HubReturn run = flyCaricTeamBox1(std::nullopt, false);
  EXPECT_LT(run.nearestBox1, 8.0);  // it explored box 1
  EXPECT_GT(run.backAt, 0.0);       // and came back to the hub
  EXPECT_LT(run.backAt, 250.0);
}

// A caric-team e1 with inspector i1 in sight, its first box box 0 by the hub (box 0's corner),
// finds feature 7 at 0.5 s and meets the station at 1 s; the reply gives it box 1, 40 m away. It
// hands the feature out at the hub before it leaves, then goes on to box 1. (The hand-out was
// checked only while it explored, by then away from the hub: on slei-a nothing was handed out
// before a box was explored.)
TEST(Slei3dExplorer, CaricTeamHandsOutAtTheHubBeforeItGoesOnToItsBox) {
  auto explorer = makeExplorer(
      Config::fromText("", "run.ini"), "caric-team",
      {{"gcs", Role::GroundStation}, {"e1", Role::Explorer}, {"i1", Role::Photographer}});
  FleetPlan plan;
  plan.subgroups.push_back({1, {2}, 0, {cornerOf(0), 400.0}, 0});
  Reply reply;
  reply.meetingNumber = 1;
  reply.box = 1;
  reply.next = {cornerOf(0), 400.0};
  reply.stops = {reply.next};
  agent::AgentView view = startView();
  agent::NeighbourInfo inspector{"i1", Role::Photographer, {}};
  inspector.odometry.position = Vec3(-6, 4, 3);
  view.neighbours = {inspector};
  double ordersAt = -1.0, atBox1 = -1.0;  // s, -1: never
  std::set<uint32_t> handed;
  std::vector<agent::ReceivedMessage> answers;
  for (int step = 0; step * 0.1 <= 150.0 && atBox1 < 0.0; ++step) {
    view.time = step * 0.1;
    view.messages = std::move(answers);
    answers.clear();
    if (step == 0) view.messages.push_back({"gcs", kPlanTopic, encode(plan)});
    if (step == 10) view.messages.push_back({"gcs", kReplyTopic, encode(reply)});
    view.detectedFeatures.clear();
    if (step == 5) view.detectedFeatures.push_back({7, Vec3(-3, 8, 2), -Vec3::UnitY(), 2.0});
    const auto command = explorer->decide(view);
    if (command.setpoint) view.odometry.position = command.setpoint->position;
    for (const auto& message : command.messages) {
      const auto orders =
          message.topic == kOrdersTopic ? decodeOrders(message.bytes) : std::nullopt;
      if (!orders) continue;
      if (ordersAt < 0.0) ordersAt = view.time;
      for (const auto& task : orders->tasks)
        handed.insert(task.id);
      Status status;  // taken: the list still to do
      status.lastOrders = orders->sequence;
      status.listLeft = static_cast<uint32_t>(orders->tasks.size());
      answers.push_back({message.to, kStatusTopic, encode(status), view.time});
    }
    if ((view.odometry.position - kBoxes[1].center).head<2>().norm() < 8.0) atBox1 = view.time;
  }
  EXPECT_EQ(handed, (std::set<uint32_t>{7}));
  EXPECT_GT(ordersAt, 0.0);
  EXPECT_GT(atBox1, ordersAt);  // handed out first, then on to its box
}

// Where e1, a caric-team explorer with nothing left, waits at its static station's hub (6, 0)
// after 60 s, when it is the `slot`-th of the station's two explorers in the plan: above its own
// side, 3 m out (the first towards +x), 6 m from the other, and 6 m above the 3 m where the
// inspectors wait. (Both waited at the one point nearest the station, and the lower-priority
// one, backed off to the flight's 4 m separation, was out of the station's link; on its side at
// the inspectors' height, one held an inspector at the hub.)
Vec3 hubWait(size_t slot) {
  auto explorer =
      makeExplorer(Config::fromText("", "run.ini"), "caric-team",
                   {{"gcs", Role::GroundStation}, {"e1", Role::Explorer}, {"e2", Role::Explorer}});
  const Meeting hub{Vec3(6, 0, 0), 400.0};
  FleetPlan plan;
  plan.subgroups = {{2, {}, -1, hub, 0}, {2, {}, -1, hub, 0}};
  plan.subgroups[slot].explorer = 1;
  agent::AgentView view = startView();
  for (int step = 0; step * 0.1 <= 60.0; ++step) {
    view.time = step * 0.1;
    view.messages.clear();
    if (step == 0) view.messages.push_back({"gcs", kPlanTopic, encode(plan)});
    const auto command = explorer->decide(view);
    if (command.setpoint) view.odometry.position = command.setpoint->position;
  }
  return view.odometry.position;
}

TEST(Slei3dExplorer, CaricTeamExplorersWaitOnTheirOwnSideOfTheHub) {
  const Vec3 first = hubWait(0), second = hubWait(1);
  EXPECT_LT((first.head<2>() - Eigen::Vector2d(9, 0)).norm(), 0.5);
  EXPECT_LT((second.head<2>() - Eigen::Vector2d(3, 0)).norm(), 0.5);
  EXPECT_GT(first.z(), 8.5);
  EXPECT_GT(second.z(), 8.5);
}

// The time e1 first sends orders to i1 (its one inspector, always in sight) after it found a
// feature at 2 s, exploring box 0 (meeting at 400 s), and when it ended its roof pass over the
// box (over its far corner, above 5 m: until then the box is left to explore).
struct HandoutTiming {
  double firstOrders = -1.0;
  double roofPassEnd = -1.0;
};

// e1 detects feature 7 at 2 s with i1 in sight; at `resultAt` s (if >= 0) it receives 7's
// inspection result (from another subgroup, through the station). With `reserveNext`, a reply at
// 1 s (as if met on the way) keeps box 0 and reserves box 1 after it. With `paintedWaitPoint`, a
// LiDAR sweep at 0.5 s maps a body at i1's wait point, as the map paints an inspector seen there
// out of link (SOEI samples no meeting point around it), and e1 finds features 8-10 with 7 (with
// 7 alone, SOEI's costs chose not to meet at the one candidate left until the box's end).
HandoutTiming handoutWhileExploring(const Config& config, bool highPriority, double resultAt = -1.0,
                                    bool reserveNext = false, bool paintedWaitPoint = false) {
  auto body = std::make_shared<std::vector<Eigen::Vector3f>>();
  const Eigen::Vector3f waitPoint(-7.9f, 5.6f, 6.0f);  // i1's first wait point
  for (float x = -0.3f; x <= 0.31f; x += 0.1f)
    for (float y = -0.3f; y <= 0.31f; y += 0.1f)
      for (float z = -0.3f; z <= 0.31f; z += 0.1f)
        body->push_back(waitPoint + Eigen::Vector3f(x, y, z));
  auto explorer = makeExplorer(
      config, "slei3d",
      {{"gcs", Role::GroundStation}, {"e1", Role::Explorer}, {"i1", Role::Photographer}});
  FleetPlan plan;
  plan.subgroups.push_back({1, {2}, 0, {cornerOf(0), 400.0}, 0});
  agent::AgentView view = startView();
  agent::NeighbourInfo inspector{"i1", Role::Photographer, {}};
  inspector.odometry.position = Vec3(-6, 4, 3);
  HandoutTiming timing;
  for (int step = 0; step * 0.1 <= 120.0 && timing.firstOrders < 0.0; ++step) {
    view.time = step * 0.1;
    view.messages.clear();
    if (step == 0) view.messages.push_back({"gcs", kPlanTopic, encode(plan)});
    if (step == 10 && reserveNext)
      view.messages.push_back({"gcs", kReplyTopic, encode(keepBox0(1, 400.0))});
    view.neighbours = {inspector};
    if (step == 5 && paintedWaitPoint) view.lidar = {0.5, view.odometry.position, body};
    view.detectedFeatures.clear();
    view.receivedResults.clear();
    if (step == 20)
      view.detectedFeatures.push_back({7, Vec3(0, 8, 2), -Vec3::UnitY(), 2.0, highPriority});
    for (uint32_t f = 8; step == 20 && paintedWaitPoint && f < 11; ++f)
      view.detectedFeatures.push_back(
          {f, Vec3(-1.5 + 0.5 * (f - 8), 8, 1.0), -Vec3::UnitY(), 2.0, highPriority});
    if (resultAt >= 0.0 && step == static_cast<int>(std::lround(resultAt * 10.0)))
      view.receivedResults.push_back(7);
    const auto command = explorer->decide(view);
    if (command.setpoint) view.odometry.position = command.setpoint->position;
    const Vec3& at = view.odometry.position;
    if (timing.roofPassEnd < 0.0 && at.z() > 5.0 &&
        (at.head<2>() - Eigen::Vector2d(2, 12)).norm() < 0.5)
      timing.roofPassEnd = view.time;  // over the far corner: the roof pass is flown
    for (const auto& message : command.messages)
      if (message.to == "i1" && message.topic == kOrdersTopic && timing.firstOrders < 0.0)
        timing.firstOrders = view.time;
  }
  return timing;
}

// With `handout_at_box_end` the feature found while the box is left to explore waits until the
// box is explored (the roof pass flown); SOEI alone hands it to the inspector in sight at once,
// and so does the explorer holding a high-priority feature.
TEST(Slei3dExplorer, WithHandoutAtBoxEndItHandsOutOnlyOnceItsBoxIsExplored) {
  const auto soei = handoutWhileExploring(Config::fromText("", "run.ini"), false);
  const auto config = Config::fromText("[slei3d]\nhandout_at_box_end = true\n", "run.ini");
  const auto held = handoutWhileExploring(config, false);
  const auto urgent = handoutWhileExploring(config, true);
  ASSERT_GT(soei.firstOrders, 0.0);
  ASSERT_GT(held.firstOrders, 0.0);
  ASSERT_GT(held.roofPassEnd, 0.0);
  EXPECT_LT(soei.firstOrders, held.roofPassEnd);
  EXPECT_GE(held.firstOrders, held.roofPassEnd);
  EXPECT_LT(urgent.firstOrders, held.roofPassEnd);
}

// In its last box (no next box reserved) it holds what it finds only `last_box_hold` s: the
// feature found at 2 s goes out before the box is explored (where it goes out when held to the
// box's end), also to an inspector around which SOEI sampled no meeting point. With a next box
// reserved it is held to the box's end all the same.
TEST(Slei3dExplorer, InItsLastBoxItHandsOutWhatItHeldTooLong) {
  const auto config = [](const char* hold) {
    return Config::fromText(
        std::string("[slei3d]\nhandout_at_box_end = true\nlast_box_hold = ") + hold + "\n",
        "run.ini");
  };
  const auto held = handoutWhileExploring(config("0"), false);
  const auto released = handoutWhileExploring(config("5"), false);
  const auto reserved = handoutWhileExploring(config("5"), false, -1.0, true);
  const auto painted = handoutWhileExploring(config("5"), false, -1.0, false, true);
  const auto paintedHeld = handoutWhileExploring(config("0"), false, -1.0, false, true);
  ASSERT_GT(held.roofPassEnd, 0.0);
  ASSERT_GT(held.firstOrders, 0.0);
  EXPECT_GE(held.firstOrders, held.roofPassEnd);
  ASSERT_GT(released.firstOrders, 0.0);
  EXPECT_GE(released.firstOrders, 7.0);
  EXPECT_LT(released.firstOrders, held.firstOrders);
  ASSERT_GT(reserved.roofPassEnd, 0.0);
  EXPECT_GE(reserved.firstOrders, reserved.roofPassEnd);
  // No point sampled around the inspector: it is met where its plan ends, as at the box's end.
  ASSERT_GT(paintedHeld.roofPassEnd, 0.0);
  EXPECT_GE(paintedHeld.firstOrders, paintedHeld.roofPassEnd);
  ASSERT_GT(painted.firstOrders, 0.0);
  EXPECT_GE(painted.firstOrders, 7.0);
  EXPECT_LT(painted.firstOrders, paintedHeld.roofPassEnd);
}

// A feature whose result it carries is not handed out: neither one detected after the result
// came (SOEI would hand it out at once), nor one it held when the result came (held for the end
// of the box, past the roof pass).
TEST(Slei3dExplorer, AFeatureWhoseResultItCarriesIsNotHandedOut) {
  const auto known = handoutWhileExploring(Config::fromText("", "run.ini"), false, 1.0);
  EXPECT_LT(known.firstOrders, 0.0);
  const auto config = Config::fromText("[slei3d]\nhandout_at_box_end = true\n", "run.ini");
  const auto heldThenKnown = handoutWhileExploring(config, false, 3.0);
  ASSERT_GT(heldThenKnown.roofPassEnd, 3.0);
  EXPECT_LT(heldThenKnown.firstOrders, 0.0);
}

using Cloud = std::shared_ptr<std::vector<Eigen::Vector3f>>;

// Points on the box [from, to] every 0.25 m.
Cloud pointsIn(const Eigen::Vector3f& from, const Eigen::Vector3f& to) {
  auto cloud = std::make_shared<std::vector<Eigen::Vector3f>>();
  for (float x = from.x(); x <= to.x(); x += 0.25f)
    for (float y = from.y(); y <= to.y(); y += 0.25f)
      for (float z = from.z(); z <= to.z(); z += 0.25f)
        cloud->emplace_back(x, y, z);
  return cloud;
}

// The features in each orders e1 sends to its two inspectors i1 and i2 once it found
// `features` (at 2 s; by default two, 6 m apart) and its box is explored. The two stay in sight
// (at (-6, 4, 3) and (6, 4, 3)), idle; e1 plans to meet them at their first wait points,
// (-7.9, 5.6, 6) and (-4.4, 2.1, 6). One LiDAR sweep at 0.5 s maps `scan` from the start.
std::map<std::string, std::set<uint32_t>> handOutAfter(
    const Cloud& scan, const std::vector<Vec3>& features = {Vec3(-3, 8, 2), Vec3(3, 8, 2)},
    const char* config = "", const char* strategy = "slei3d") {
  auto explorer = makeExplorer(Config::fromText(config, "run.ini"), strategy,
                               {{"gcs", Role::GroundStation},
                                {"e1", Role::Explorer},
                                {"i1", Role::Photographer},
                                {"i2", Role::Photographer}});
  FleetPlan plan;
  plan.subgroups.push_back({1, {2, 3}, 0, {cornerOf(0), 400.0}, 0});
  agent::AgentView view = startView();
  std::map<std::string, std::set<uint32_t>> tasks;
  std::vector<agent::ReceivedMessage> answers;
  for (int step = 0; step * 0.1 <= 120.0; ++step) {
    view.time = step * 0.1;
    view.messages = std::move(answers);
    answers.clear();
    if (step == 0) view.messages.push_back({"gcs", kPlanTopic, encode(plan)});
    view.neighbours.clear();
    for (const char* name : {"i1", "i2"}) {
      agent::NeighbourInfo inspector{name, Role::Photographer, {}};
      inspector.odometry.position = Vec3(name[1] == '1' ? -6 : 6, 4, 3);
      view.neighbours.push_back(inspector);
    }
    if (step == 5) view.lidar = {0.5, view.odometry.position, scan};
    view.detectedFeatures.clear();
    if (step == 20) {
      for (size_t k = 0; k < features.size(); ++k)
        view.detectedFeatures.push_back(
            {static_cast<uint32_t>(7 + k), features[k], -Vec3::UnitY(), 2.0});
    }
    const auto command = explorer->decide(view);
    if (command.setpoint) view.odometry.position = command.setpoint->position;
    for (const auto& message : command.messages) {
      if (message.topic != kOrdersTopic) continue;
      const auto orders = decodeOrders(message.bytes);
      EXPECT_TRUE(orders);
      if (!orders) continue;
      for (const auto& task : orders->tasks)
        tasks[message.to].insert(task.id);
      Status status;  // taken: the list still to do
      status.lastOrders = orders->sequence;
      status.listLeft = static_cast<uint32_t>(orders->tasks.size());
      answers.push_back({message.to, kStatusTopic, encode(status), view.time});
    }
  }
  return tasks;
}

// caric-team at its hub (box 0's corner, where it explores): four features go to its two
// inspectors, in sight and free, in two runs of a nearest-neighbour tour: two each, the two
// nearer each other together. (All went to the one free soonest: with its returns 300 s apart,
// the other one idled.)
TEST(Slei3dExplorer, CaricTeamSplitsItsFeaturesAmongItsFreeInspectors) {
  const auto tasks = handOutAfter(std::make_shared<std::vector<Eigen::Vector3f>>(),
                                  {Vec3(-3, 8, 2), Vec3(-2, 8, 2), Vec3(3, 8, 2), Vec3(4, 8, 2)},
                                  "", "caric-team");
  ASSERT_EQ(tasks.size(), 2u);
  const auto& first = tasks.begin()->second;
  const auto& second = tasks.rbegin()->second;
  EXPECT_EQ(first.size(), 2u);
  EXPECT_EQ(second.size(), 2u);
  // Features 7 and 8 at x -3 and -2, 9 and 10 at 3 and 4.
  EXPECT_TRUE(first == (std::set<uint32_t>{7, 8}) || first == (std::set<uint32_t>{9, 10}));
  EXPECT_TRUE(second == (std::set<uint32_t>{7, 8}) || second == (std::set<uint32_t>{9, 10}));
}

TEST(Slei3dExplorer, WithNoMeetingPointFoundTheFeaturesAreSplitAmongItsInspectors) {
  // A wall of points at z 4.5 to 8 m over both wait points: no meeting point anywhere near them.
  const auto tasks = handOutAfter(pointsIn({-12, -3, 4.5}, {12, 6.5, 8}));
  EXPECT_EQ(tasks.count("i1") ? tasks.at("i1").size() : 0u, 1u);
  EXPECT_EQ(tasks.count("i2") ? tasks.at("i2").size() : 0u, 1u);
}

TEST(Slei3dExplorer, AnInspectorWithNoMeetingPointSampledIsStillMetWhereItWaits) {
  // Points on i1's wait point, as the explorer's map paints an inspector it saw beyond the link:
  // no sight line reaches that pose, so SOEI samples no meeting point around it (only around
  // i2's), yet the explorer can meet i1 from beside it. Handed out once the box is explored
  // (an in-box hand-out may leave an inspector out when SOEI finds that cheaper).
  std::vector<Vec3> features;  // eight along the box's near face, too many for one inspector
  for (int k = 0; k < 8; ++k)
    features.emplace_back(-3.5 + k, 8, 2);
  const auto tasks = handOutAfter(pointsIn({-8.1f, 5.4f, 5.8f}, {-7.7f, 5.8f, 6.2f}), features,
                                  "[slei3d]\nhandout_at_box_end = true\n");
  EXPECT_EQ(tasks.count("i1") ? tasks.at("i1").size() : 0u, 4u);
  EXPECT_EQ(tasks.count("i2") ? tasks.at("i2").size() : 0u, 4u);
}

}  // namespace
}  // namespace coinspect::strategies::slei
