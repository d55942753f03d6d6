// slei3d, the ground station: the first plan, then from meeting to meeting, answering reports.
#include <algorithm>
#include <cmath>

#include "coinspect/planning/slei_meeting_order.h"
#include "coinspect/strategies/slei/slei3d_strategy.h"

namespace coinspect::strategies::slei {

namespace {

constexpr double kNoMeeting = 1e300;     // Reply::next.time when the explorer has nothing left
constexpr double kArrived = 0.5;         // m from a meeting place that counts as there
constexpr double kMinRemaining = 50.0;   // s (the reference's floor)
constexpr double kNewBoxLead = 60.0;     // s to the first meeting in a new box (the reference)
constexpr double kPresumedLost = 6.0;    // meeting graces after its time: the explorer is lost
constexpr double kUnreachedFor = 300.0;  // s more when the station never got there
constexpr double kRechargeLevel = 0.2;   // battery level an explorer must be back by (the paper)
constexpr double kChargeSettle = 5.0;    // s for an explorer to get above the charger
constexpr double kLargerBox = 1.01;      // a box this much larger than a free one is split
constexpr double kBesideMeeting = 2.5;   // m between two explorers' places at one meeting

}  // namespace

// The station's meetings as a TSP-TW (ids: their indices in schedule_), each window from the
// planned time to when the explorer is presumed lost; `without`'s meeting left out.
planning::MeetingOrderProblem Slei3dStrategy::scheduleProblem(
    const agent::AgentView& view, std::optional<uint32_t> without) const {
  planning::MeetingOrderProblem problem;
  problem.start = view.odometry.position;
  problem.startTime = std::max(view.time, holdUntil_);  // an explorer charging first
  problem.travelTime = planning::groundTravelTime(options_.plan.stationSpeed);
  for (size_t i = 0; i < schedule_.size(); ++i) {
    if (without && schedule_[i].explorer == *without) continue;
    planning::GcsMeeting meeting;
    meeting.id = static_cast<int>(i);
    meeting.place = schedule_[i].meeting.place;
    meeting.earliest = schedule_[i].meeting.time;
    meeting.latest = schedule_[i].meeting.time + kPresumedLost * options_.meetingGrace;
    meeting.service = kMeetingService;
    problem.meetings.push_back(meeting);
  }
  return problem;
}

// The paper's rule: the station serves its meetings in the order of a travelling-salesman path
// with time windows (planning::planMeetingOrder); the reference code simply sorts them by time.
void Slei3dStrategy::orderSchedule(const agent::AgentView& view) {
  const auto problem = scheduleProblem(view, std::nullopt);
  const auto order = planning::planMeetingOrder(problem).order;
  std::vector<StationMeeting> ordered;
  for (const int i : order)
    ordered.push_back(schedule_[static_cast<size_t>(i)]);
  schedule_ = std::move(ordered);
}

// `feasible_meetings`: the earliest time from eq. 9's on (in 10 s steps, at most 1200 s later)
// at which the station's ordered route (straight ground travel at its speed) reaches the new
// meeting within meetingGrace and no other meeting later than it already would (the others were
// promised at their own replies and cannot move before their meetings). With eq. 9's time
// alone, one station at 1 m/s serving the eight explorers of slei-d came late to 84 of 102
// promised meetings, and the explorers hovered at them 68 % of their time (doc/strategies.md).
double Slei3dStrategy::feasibleMeetingTime(const agent::AgentView& view, uint32_t explorer,
                                           const Meeting& wanted) const {
  constexpr double kSlipStep = 10.0, kMaxSlip = 1200.0;
  auto problem = scheduleProblem(view, explorer);
  const double before = planning::planMeetingOrder(problem).maxLateness;
  planning::GcsMeeting mine;
  mine.id = -1;
  mine.place = wanted.place;
  mine.service = kMeetingService;
  problem.meetings.push_back(mine);
  for (double slip = 0.0; slip <= kMaxSlip; slip += kSlipStep) {
    problem.meetings.back().earliest = wanted.time + slip;
    problem.meetings.back().latest = wanted.time + slip + options_.meetingGrace;
    const auto after = planning::planMeetingOrder(problem);
    const auto own = std::find_if(after.stops.begin(), after.stops.end(),
                                  [](const auto& stop) { return stop.id == -1; });
    if (after.maxLateness <= before + 1e-6 && own != after.stops.end() && own->lateness <= 0.0)
      return wanted.time + slip;
  }
  return wanted.time;
}

void Slei3dStrategy::answerReports(const agent::AgentView& view, agent::AgentCommand& command) {
  for (const auto& message : view.messages) {
    if (message.topic != kReportTopic) continue;
    const auto report = decodeReport(message.bytes);
    const auto from = std::find(names_.begin(), names_.end(), message.from);
    if (!report || from == names_.end()) continue;
    const auto explorer = static_cast<uint32_t>(from - names_.begin());
    if (unit_.fleet[explorer].role != agent::Role::Explorer) continue;
    const auto previous = answered_.find(explorer);
    if (previous != answered_.end() && previous->second.meetingNumber == report->meetingNumber) {
      send(command, explorer, kReplyTopic, encode(previous->second));  // a lost reply: again
      continue;
    }
    // Waiting for a share of another's box, it is answered at its meeting's time: the one at
    // work, met there just before, may have left it a part.
    if (awaitingWork_.count(explorer) && report->box < 0 && previous != answered_.end() &&
        view.time < previous->second.next.time)
      continue;
    Reply reply;
    reply.meetingNumber = report->meetingNumber;
    // Presumed lost, it turns up again: its inspectors went to others, and it starts afresh.
    if (lost_.erase(explorer) > 0) {
      reply.dropInspectors = true;
      members_[explorer].clear();
    }
    reply.box = report->box;
    double lead = std::clamp(report->remaining, kMinRemaining,
                             std::max(kMinRemaining, options_.maxMeetingLead));
    const Vec3 here = view.odometry.position;
    const bool known = report->box >= 0 && static_cast<size_t>(report->box) < boxes_.size();
    // Done before this meeting, it went on to the box the last reply reserved: its box now.
    const auto reservation = reserved_.find(explorer);
    const bool movedOn = reservation != reserved_.end() && report->box == reservation->second;
    if (movedOn) reserved_.erase(reservation);
    const auto largestFree = [&] {
      double largest = 0.0;
      for (size_t b = 0; b < boxes_.size(); ++b)
        if (!boxTaken_[b]) largest = std::max(largest, boxes_[b].size.prod());
      return largest;
    };
    // Work sharing: another explorer waits for a share of this one's work. The box reserved
    // for this one, not started, goes back to the free ones (the waiting one takes it at its
    // meeting); with none reserved and none free, the box is split (below).
    const bool othersWait =
        sharingWork() && known && !report->boxFinished && !movedOn && othersAwaitWork(explorer);
    if (othersWait && reservation != reserved_.end()) {
      returnBox(explorer, reservation->second);
      reserved_.erase(reservation);
    }
    const bool share = othersWait && report->remainder.size() > 1 && freeBoxCount() == 0;
    const bool unknownSplit =
        options_.unknownWorkspace && !fixedRegions() && known && !report->boxFinished &&
        !report->remainder.empty() &&
        boxes_[static_cast<size_t>(report->box)].size.prod() > kLargerBox * largestFree();
    if (unknownSplit || share) {
      // The paper's octree partition of what is left, for a box larger than every free one (so
      // the next subgroup done with its own finds one; the work stays in boxes of about one
      // size): the box's parts with work join the free boxes (the box itself stays taken: its
      // parts replace it), and the subgroup goes on with the one nearest the meeting, its share
      // of eq. 9's time by volume to the next meeting. (Split at every meeting, each explorer
      // met the station every minute for a part of ever less work: 33 collected of 150 on
      // slei-a, scene seed 1.)
      double left = 0.0;
      for (const auto& part : report->remainder) {
        boxes_.push_back(part);
        boxTaken_.push_back(0);
        left += part.size.prod();
      }
      reply.box = nearestFreeBox(boxes_, boxTaken_, here);
      boxTaken_[static_cast<size_t>(reply.box)] = 1;
      const double share = boxes_[static_cast<size_t>(reply.box)].size.prod() / left;
      lead = std::clamp(report->remaining * share, kMinRemaining,
                        std::max(kMinRemaining, options_.maxMeetingLead));
    }
    if (report->boxFinished && known) {
      // Rolling assignment: the free box nearest the finished one, for the whole subgroup
      // (slei-pre: the next of its fixed order), or the one reserved for it at the last reply.
      const auto next = reserved_.find(explorer);
      if (next != reserved_.end()) {
        reply.box = next->second;
        reserved_.erase(next);
      } else {
        reply.box = takeNextBox(explorer, report->box);
      }
      if (reply.box >= 0) lead = kNewBoxLead;
    } else if (report->box < 0 && awaitingWork_.count(explorer)) {
      reply.box = nearestFreeBox(boxes_, boxTaken_, here);  // a share left by one at work
      if (reply.box >= 0) {
        boxTaken_[static_cast<size_t>(reply.box)] = 1;
        lead = kNewBoxLead;
      }
    }
    // Left without a box while others explore: it waits for a share at the next meeting of one
    // at work (an explorer whose battery limits it charges and comes back instead: not here).
    const StationMeeting* atWork = nextMeetingAtWork(explorer);
    const bool awaiting =
        reply.box < 0 && sharingWork() && atWork && !unit_.fleet[explorer].battery.limited();
    if (awaiting)
      awaitingWork_.insert(explorer);
    else
      awaitingWork_.erase(explorer);
    // The box after it, reserved now: an explorer done before its next meeting goes on to it
    // rather than wait for the station, which cannot know it is done (slei-a: explorers done
    // with a small box waited up to 480 s for a meeting eq. 9 had put 600 s ahead).
    if (options_.reserveNextBox && !options_.unknownWorkspace && reply.box >= 0 &&
        !reserved_.count(explorer) && (fixedRegions() || freeBoxesSpare(explorer))) {
      const int32_t next = takeNextBox(explorer, reply.box);
      if (next >= 0) reserved_[explorer] = next;
    }
    const auto reservedNow = reserved_.find(explorer);
    reply.nextBox = reservedNow != reserved_.end() ? reservedNow->second : -1;
    reply.boxShape = partShape(reply.box);
    reply.nextBoxShape = partShape(reply.nextBox);
    if (awaiting) {
      // Just after that meeting and beside it, away from that one's box: the two do not hover
      // at one point, and both are within a link of the station there.
      Vec3 away =
          atWork->meeting.place - boxes_[static_cast<size_t>(boxOf(atWork->explorer))].center;
      away.z() = 0.0;
      away = away.norm() > 1e-6 ? away.normalized() : Vec3::UnitX();
      reply.next = {atWork->meeting.place + kBesideMeeting * away,
                    std::max(atWork->meeting.time, view.time) + options_.meetingGrace};
    } else if (reply.box < 0 && report->boxFinished && report->box < 0 &&
               report->remaining <= 0.0) {
      reply.next = {here, kNoMeeting};  // nothing left for this subgroup
    } else {
      // The corner nearest the station (the reference's rule). The paper's, the corner whose
      // arrival time best matches the planned time (planning::bestTimedMeetingCorner), was
      // tried only while the station drove straight (it stopped at a wall on the far side of a
      // box for the rest of a slei-a run); not yet with its ground paths.
      Vec3 place = reply.box >= 0 ? boxCorner(boxes_, static_cast<size_t>(reply.box),
                                              options_.plan.cornerOffset, here.z(), here)
                                  : here;
      if (options_.unknownWorkspace && reply.box >= 0) {
        // The parts tile the area and their corners may stand in a structure: the box's own
        // nearest corner, then the ground the station can reach nearest to it (the walls it has
        // learnt from the key frames it carries).
        place = boxCorner(boxes_[static_cast<size_t>(reply.box)], options_.plan.cornerOffset,
                          here.z(), here);
        const planning::Vec2 reach =
            drive_->ground().nearestReachable(here.head<2>(), place.head<2>());
        place = Vec3(reach.x(), reach.y(), here.z());
      }
      if (staticStation()) place = staticPlace_, lead = returnInterval();
      // [energy] (the paper's eq. 15): the explorer charges first, the station waiting for it,
      // and must be back before its battery falls to 20 %: the meeting moves by the charging
      // time and comes no later than the charge allows.
      // One charger: an explorer that finds another charging waits for it, losing charge.
      double start = view.time;
      const auto& battery = unit_.fleet[explorer].battery;
      if (battery.limited() && report->energy < 1.0) {
        reply.chargeFrom = std::max(view.time, holdUntil_);
        const double level =
            std::max(0.0, report->energy - (reply.chargeFrom - view.time) / battery.capacity);
        start = reply.chargeFrom + (1.0 - level) * battery.chargeTime + kChargeSettle;
        holdUntil_ = start;
      }
      if (battery.limited()) lead = std::min(lead, (1.0 - kRechargeLevel) * battery.capacity);
      reply.next = {place, start + lead};
      if (options_.feasibleMeetings && !staticStation())
        reply.next.time = feasibleMeetingTime(view, explorer, reply.next);
    }
    // Its inspectors wait off the new box's corner nearest where it came from (here, within a
    // link of it); a lost explorer's inspectors go to the next explorer with a box that reports.
    if (reply.box >= 0 && (reply.box != report->box || movedOn) &&
        options_.variant != SleiVariant::Team) {
      enteredFrom_[explorer] = here;
      auto& members = members_[explorer];
      for (size_t k = 0; k < members.size(); ++k)
        members[k].place = waitPointNear(reply.box, here, k);
    }
    if (reply.box >= 0 && !orphans_.empty() && members_.count(explorer)) {
      auto& members = members_[explorer];
      for (const auto& orphan : orphans_) {
        reply.adopt.push_back(orphan);
        members.push_back({orphan.inspector,
                           options_.variant == SleiVariant::Team
                               ? orphan.place
                               : waitPointNear(reply.box, enteredFrom_[explorer], members.size())});
      }
      orphans_.clear();
    }
    schedule_.erase(std::remove_if(schedule_.begin(), schedule_.end(),
                                   [&](const StationMeeting& m) { return m.explorer == explorer; }),
                    schedule_.end());
    if (reply.next.time < kNoMeeting) schedule_.push_back({explorer, reply.next});
    orderSchedule(view);
    for (const auto& stop : schedule_)
      reply.stops.push_back(stop.meeting);
    answered_[explorer] = reply;
    send(command, explorer, kReplyTopic, encode(reply));
  }
}

void Slei3dStrategy::orphanInspectors(uint32_t explorer) {
  const auto members = members_.find(explorer);
  if (members == members_.end()) return;
  for (const auto& m : members->second)
    orphans_.push_back({m.inspector, m.place});
  members_.erase(members);
  lost_.insert(explorer);
  awaitingWork_.erase(explorer);
}

// A lost explorer's box and the one reserved for it go back. It may have finished the first
// and gone on to the second: the station cannot tell, so both are explored again.
void Slei3dStrategy::releaseBox(uint32_t explorer) {
  const auto answered = answered_.find(explorer);
  int32_t box = answered != answered_.end() ? answered->second.box : -1;
  if (answered == answered_.end() && plan_)
    for (const auto& s : plan_->subgroups)
      if (s.explorer == explorer) box = s.box;
  returnBox(explorer, box);
  const auto next = reserved_.find(explorer);
  if (next == reserved_.end()) return;
  const int32_t reserved = next->second;
  reserved_.erase(next);
  returnBox(explorer, reserved);
}

void Slei3dStrategy::returnBox(uint32_t explorer, int32_t box) {
  if (box < 0) return;
  if (!fixedRegions()) {
    boxTaken_[static_cast<size_t>(box)] = 0;
    return;
  }
  giveBoxToShortestOrder(boxOrder_, subgroupIndex(explorer), box);
}

// Rolling assignment: a free box is reserved for `explorer` only while one stays free for every
// other explorer that works in a box with none reserved, which will ask for one first; reserved
// at once, the last free box went to whichever explorer asked for it last. (On slei-a, scene
// seeds 1-3, no run changed: there the late imbalance comes from reservations made while each
// explorer still had one of its own.)
bool Slei3dStrategy::freeBoxesSpare(uint32_t explorer) const {
  const size_t free = freeBoxCount();
  size_t asking = 0;
  for (const auto& s : plan_->subgroups) {
    if (s.explorer == explorer || lost_.count(s.explorer) || reserved_.count(s.explorer)) continue;
    if (boxOf(s.explorer) >= 0 || awaitingWork_.count(s.explorer)) ++asking;
  }
  return free > asking;
}

size_t Slei3dStrategy::freeBoxCount() const {
  return static_cast<size_t>(std::count(boxTaken_.begin(), boxTaken_.end(), uint8_t{0}));
}

int32_t Slei3dStrategy::boxOf(uint32_t explorer) const {
  const auto answered = answered_.find(explorer);
  if (answered != answered_.end()) return answered->second.box;
  const size_t index = subgroupIndex(explorer);
  return index < plan_->subgroups.size() ? plan_->subgroups[index].box : -1;
}

bool Slei3dStrategy::othersAwaitWork(uint32_t explorer) const {
  return std::any_of(awaitingWork_.begin(), awaitingWork_.end(),
                     [&](uint32_t other) { return other != explorer && !lost_.count(other); });
}

const Slei3dStrategy::StationMeeting* Slei3dStrategy::nextMeetingAtWork(uint32_t explorer) const {
  const StationMeeting* earliest = nullptr;
  for (const auto& m : schedule_) {
    if (m.explorer == explorer || awaitingWork_.count(m.explorer) || lost_.count(m.explorer))
      continue;
    if (boxOf(m.explorer) < 0) continue;
    if (!earliest || m.meeting.time < earliest->meeting.time) earliest = &m;
  }
  return earliest;
}

std::optional<agent::BoxView> Slei3dStrategy::partShape(int32_t box) const {
  if (box < 0 || (!options_.unknownWorkspace && static_cast<size_t>(box) < sceneBoxes_))
    return std::nullopt;
  return boxes_[static_cast<size_t>(box)];
}

namespace {

// split_last_box's parts, about one per explorer that may share them: for two, halves across
// the longer side of the footprint; for more, the footprint's quarters. None when no side to
// halve is longer than leafEdge.
std::vector<agent::BoxView> lastBoxParts(const agent::BoxView& box, size_t explorers,
                                         double leafEdge) {
  if (explorers > 2) return octreeChildren(box, leafEdge, false);
  auto aligned = workspaceBox({box});  // world-aligned, as octreeChildren's parts
  aligned.highPriority = box.highPriority;
  if (std::max(aligned.size.x(), aligned.size.y()) <= leafEdge) return {};
  return splitWorkspace(aligned, 2);
}

}  // namespace

int32_t Slei3dStrategy::takeNextBox(uint32_t explorer, int32_t after) {
  int32_t box = -1;
  if (fixedRegions()) {
    const size_t index = subgroupIndex(explorer);
    auto* order = index < boxOrder_.size() ? &boxOrder_[index] : nullptr;
    if (order && !order->empty()) {
      box = order->front();
      order->erase(order->begin());
    }
  } else {
    const Vec3 from = boxes_[static_cast<size_t>(after)].center;
    box = nearestFreeBox(boxes_, boxTaken_, from);
    const size_t explorers = explorerCount();
    if (box >= 0 && options_.splitLastBox && !options_.unknownWorkspace && freeBoxCount() == 1 &&
        explorers > 1 && static_cast<size_t>(box) < sceneBoxes_) {
      // split_last_box: its parts replace it (it stays taken), the nearest given out. A part is
      // not split again.
      const auto parts =
          lastBoxParts(boxes_[static_cast<size_t>(box)], explorers, options_.leafEdge);
      if (!parts.empty()) {
        boxTaken_[static_cast<size_t>(box)] = 1;
        for (const auto& part : parts) {
          boxes_.push_back(part);
          boxTaken_.push_back(0);
        }
        box = nearestFreeBox(boxes_, boxTaken_, from);
      }
    }
  }
  if (box >= 0) boxTaken_[static_cast<size_t>(box)] = 1;
  return box;
}

// The station's explorers not presumed lost (at work, or waiting for work).
size_t Slei3dStrategy::explorerCount() const {
  return static_cast<size_t>(
      std::count_if(plan_->subgroups.begin(), plan_->subgroups.end(),
                    [&](const auto& s) { return !lost_.count(s.explorer); }));
}

size_t Slei3dStrategy::subgroupIndex(uint32_t explorer) const {
  for (size_t i = 0; i < plan_->subgroups.size(); ++i)
    if (plan_->subgroups[i].explorer == explorer) return i;
  return plan_->subgroups.size();
}

agent::AgentCommand Slei3dStrategy::decideStation(const agent::AgentView& view) {
  agent::AgentCommand command;
  const Vec3 here = view.odometry.position;
  if (!plan_) {
    // Its share of the fleet and boxes (all of them when it is the only station); the others'
    // boxes are never its to hand out.
    StationShare own;
    for (auto& share : stationShares(unit_.fleet, boxes_))
      if (share.station == unit_.self) own = std::move(share);
    for (size_t b = 0; b < boxes_.size(); ++b)
      if (!own.boxes[b]) boxTaken_[b] = 1;
    plan_ = makeFleetPlan(own, boxes_, here, groundZ_, view.time, options_.plan);
    staticPlace_ = here;
    if (staticStation())
      for (auto& s : plan_->subgroups)
        s.firstMeeting = {staticPlace_, view.time + returnInterval()};
    // [energy]: the first meeting too before a full battery is down to 20 % (the station does
    // not know the explorers' levels before their first report: full, it assumes).
    for (auto& s : plan_->subgroups) {
      const auto& battery = unit_.fleet[s.explorer].battery;
      if (battery.limited())
        s.firstMeeting.time =
            std::min(s.firstMeeting.time, view.time + (1.0 - kRechargeLevel) * battery.capacity);
    }
    if (fixedRegions()) {
      std::vector<int32_t> first;
      for (const auto& s : plan_->subgroups)
        first.push_back(s.box);
      boxOrder_ = fixedBoxOrders(boxes_, first, boxTaken_);
    }
    planBytes_ = {encode(*plan_)};
    for (const auto& s : plan_->subgroups) {
      enteredFrom_[s.explorer] = s.firstMeeting.place;
      auto& members = members_[s.explorer];
      for (size_t k = 0; k < s.inspectors.size(); ++k)
        members.push_back({s.inspectors[k], s.box >= 0 ? firstWaitPoint(s, k) : here});
    }
    for (const auto& s : plan_->subgroups) {
      if (s.box >= 0) boxTaken_[static_cast<size_t>(s.box)] = 1;
      if (s.box >= 0) schedule_.push_back({s.explorer, s.firstMeeting});
    }
    orderSchedule(view);
  }
  answerReports(view, command);
  if (view.time < holdUntil_) {  // an explorer charges above it: it stops where it is
    agent::AgentSetpoint stay;
    stay.position = here;
    command.setpoint = stay;
    command.activity = agent::Activity::Waiting;
    return command;
  }
  if (schedule_.empty()) {
    command.activity = agent::Activity::Waiting;
    return command;
  }
  // An explorer that does not come within a long grace of its meeting (and of the station's
  // arrival there) is presumed lost: the station goes on to the next one, and its box goes back
  // to the free ones (the paper's failure recovery: the next subgroup done with a box takes it).
  // An explorer that turns up again is answered as usual.
  std::vector<double> times;
  for (const auto& m : schedule_)
    times.push_back(m.meeting.time);
  const size_t serve = meetingToServe(times, view.time);
  if (serve > 0)
    std::rotate(schedule_.begin(), schedule_.begin() + static_cast<std::ptrdiff_t>(serve),
                schedule_.begin() + static_cast<std::ptrdiff_t>(serve) + 1);
  const auto& next = schedule_.front();
  // The grace runs from when the station is there: a station that comes late itself must not
  // give up an explorer that has been waiting for it.
  if (next.explorer != waitingFor_ || next.meeting.time != waitingForTime_) {
    waitingFor_ = next.explorer;
    waitingForTime_ = next.meeting.time;
    arrivedAt_.reset();
  }
  const double distance =
      std::hypot(next.meeting.place.x() - here.x(), next.meeting.place.y() - here.y());
  // As near as it gets counts too: a place its ground grid no longer reaches (walls learnt since
  // the reply) left it 1 m off, out of link of the explorer hovering 4 m off the other way, and
  // it waited there the long grace of a place never reached while every other meeting went by
  // (slei-c scene seed 3, explore-then-inspect: 1210 to 1552 s).
  const bool standing = drive_->there(next.meeting.place.head<2>());
  if ((distance <= kArrived || staticStation() || standing) && !arrivedAt_) arrivedAt_ = view.time;
  // A place it cannot get to is given up too, a long while after (kUnreachedFor).
  const double grace = kPresumedLost * options_.meetingGrace;
  const double giveUpAt = arrivedAt_ ? std::max(next.meeting.time, *arrivedAt_) + grace
                                     : next.meeting.time + grace + kUnreachedFor;
  if (view.time > giveUpAt) {
    releaseBox(next.explorer);
    orphanInspectors(next.explorer);
    schedule_.erase(schedule_.begin());
    orderSchedule(view);
    return command;
  }
  if (!staticStation()) driveStation(view, next.meeting.place, command);
  command.activity =
      distance > kArrived ? agent::Activity::TravellingToMeeting : agent::Activity::Waiting;
  return command;
}

// Along a ground path around the boxes' footprints (planning::GroundDrive). The station has no
// map: a wall outside the boxes stops it (the simulator keeps a ground vehicle out of
// structures), and a station that has not moved for a while blocks the ground just ahead of it
// and plans again.
void Slei3dStrategy::driveStation(const agent::AgentView& view, const Vec3& goal,
                                  agent::AgentCommand& command) {
  const planning::Vec2 to =
      drive_->step(view.odometry.position.head<2>(), goal.head<2>(), view.time);
  agent::AgentSetpoint setpoint;
  setpoint.position = Vec3(to.x(), to.y(), goal.z());
  command.setpoint = setpoint;
}

}  // namespace coinspect::strategies::slei
