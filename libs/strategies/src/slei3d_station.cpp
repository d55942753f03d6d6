// slei3d, the ground station: the first plan, then from meeting to meeting, answering reports.
#include <algorithm>
#include <cmath>

#include "coinspect/planning/slei_meeting_order.h"
#include "coinspect/strategies/slei/slei3d_strategy.h"

namespace coinspect::strategies::slei {

namespace {

constexpr double kNoMeeting = 1e300;  // Reply::next.time when the explorer has nothing left
constexpr double kArrived = 0.5;      // m from a meeting place that counts as there
constexpr double kMinRemaining = 50.0, kMaxRemaining = 600.0;  // s (the reference's clamps)
constexpr double kNewBoxLead = 60.0;   // s to the first meeting in a new box (the reference)
constexpr double kPresumedLost = 6.0;  // meeting graces after its time: the explorer is lost
constexpr double kService = 10.0;      // s a meeting holds the station

}  // namespace

// The paper's rule: the station serves its meetings in the order of a travelling-salesman path
// with time windows (planning::planMeetingOrder), each window from the planned time to when the
// explorer is presumed lost; the reference code simply sorts them by time.
void Slei3dStrategy::orderSchedule(const agent::AgentView& view) {
  planning::MeetingOrderProblem problem;
  problem.start = view.odometry.position;
  problem.startTime = view.time;
  problem.travelTime = planning::groundTravelTime(options_.plan.stationSpeed);
  for (size_t i = 0; i < schedule_.size(); ++i) {
    planning::GcsMeeting meeting;
    meeting.id = static_cast<int>(i);
    meeting.place = schedule_[i].meeting.place;
    meeting.earliest = schedule_[i].meeting.time;
    meeting.latest = schedule_[i].meeting.time + kPresumedLost * options_.meetingGrace;
    meeting.service = kService;
    problem.meetings.push_back(meeting);
  }
  const auto order = planning::planMeetingOrder(problem).order;
  std::vector<StationMeeting> ordered;
  for (const int i : order)
    ordered.push_back(schedule_[static_cast<size_t>(i)]);
  schedule_ = std::move(ordered);
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
    Reply reply;
    reply.meetingNumber = report->meetingNumber;
    reply.box = report->box;
    double lead = std::clamp(report->remaining, kMinRemaining, kMaxRemaining);
    if (report->boxFinished && report->box >= 0) {
      // Rolling assignment: the free box nearest the finished one, for the whole subgroup.
      reply.box =
          nearestFreeBox(boxes_, boxTaken_, boxes_[static_cast<size_t>(report->box)].center);
      if (reply.box >= 0) {
        boxTaken_[static_cast<size_t>(reply.box)] = 1;
        lead = kNewBoxLead;
      }
    }
    const Vec3 here = view.odometry.position;
    if (report->boxFinished && report->box < 0 && report->remaining <= 0.0) {
      reply.next = {here, kNoMeeting};  // nothing left for this subgroup
    } else {
      // The corner nearest the station (the reference's rule). The paper's, the corner whose
      // arrival time best matches the planned time (planning::bestTimedMeetingCorner), needs
      // the station's ground paths: driving straight, it stopped at a wall on the far side of a
      // box for the rest of a slei-a run.
      const Vec3 place = reply.box >= 0 ? boxCorner(boxes_[static_cast<size_t>(reply.box)],
                                                    options_.plan.cornerOffset, here.z(), here)
                                        : here;
      reply.next = {place, view.time + lead};
    }
    answered_[explorer] = reply;
    send(command, explorer, kReplyTopic, encode(reply));
    schedule_.erase(std::remove_if(schedule_.begin(), schedule_.end(),
                                   [&](const StationMeeting& m) { return m.explorer == explorer; }),
                    schedule_.end());
    if (reply.next.time < kNoMeeting) schedule_.push_back({explorer, reply.next});
    orderSchedule(view);
  }
}

agent::AgentCommand Slei3dStrategy::decideStation(const agent::AgentView& view) {
  agent::AgentCommand command;
  const Vec3 here = view.odometry.position;
  if (!plan_) {
    plan_ = makeFleetPlan(unit_.fleet, boxes_, here, groundZ_, view.time, options_.plan);
    planBytes_ = encode(*plan_);
    for (const auto& s : plan_->subgroups) {
      if (s.box >= 0) boxTaken_[static_cast<size_t>(s.box)] = 1;
      if (s.box >= 0) schedule_.push_back({s.explorer, s.firstMeeting});
    }
    orderSchedule(view);
  }
  answerReports(view, command);
  if (schedule_.empty()) {
    command.activity = agent::Activity::Waiting;
    return command;
  }
  // An explorer that does not come within a long grace of its meeting is presumed lost: the
  // station goes on to the next one.
  const auto& next = schedule_.front();
  if (view.time > next.meeting.time + kPresumedLost * options_.meetingGrace) {
    schedule_.erase(schedule_.begin());
    orderSchedule(view);
    return command;
  }
  const double distance =
      std::hypot(next.meeting.place.x() - here.x(), next.meeting.place.y() - here.y());
  agent::AgentSetpoint setpoint;
  setpoint.position = next.meeting.place;
  command.setpoint = setpoint;
  command.activity =
      distance > kArrived ? agent::Activity::TravellingToMeeting : agent::Activity::Waiting;
  return command;
}

}  // namespace coinspect::strategies::slei
