// The messages of the SLEI strategies (doc/strategies.md, "SLEI3D"). Times are simulated
// seconds (AgentView::time, the same clock for every robot); units are fleet indices. Every
// decoder returns nothing for a malformed message, which the receiver then ignores.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "coinspect/agent/observations.h"

namespace coinspect::strategies::slei {

using agent::Vec3;

inline constexpr const char* kPlanTopic = "slei/plan";      // station -> everyone, flooded
inline constexpr const char* kReportTopic = "slei/report";  // explorer -> station
inline constexpr const char* kReplyTopic = "slei/reply";    // station -> explorer
inline constexpr const char* kOrdersTopic = "slei/orders";  // explorer -> inspector
// s a meeting holds the station: it plans its meeting order with it, and an explorer done early
// with it predicts where the station will be.
inline constexpr double kMeetingService = 10.0;
inline constexpr const char* kStatusTopic = "slei/status";  // inspector -> explorer

// A feature to inspect and the pose to inspect it from (the explorer's pose when it detected it:
// a place the explorer flew through, so free for the smaller inspector too).
struct FeatureTask {
  uint32_t id = 0;
  Vec3 position = Vec3::Zero();
  Vec3 normal = Vec3::Zero();
  Vec3 viewPosition = Vec3::Zero();
  double viewYaw = 0.0;
  // The explorer's own knowledge (not sent: an inspector visits its list in the order given).
  bool highPriority = false;
};

struct Meeting {
  Vec3 place = Vec3::Zero();
  double time = 0.0;
};

// The station's initial plan: one subgroup per explorer. With several stations each one plans
// its own subgroups (fleet_plan.h, stationShares) and the robots merge the parts they receive.
struct Subgroup {
  uint32_t explorer = 0;
  std::vector<uint32_t> inspectors;
  int32_t box = -1;  // index into the mission's boxes; -1: none
  Meeting firstMeeting;
  uint32_t station = 0;  // the ground station it meets (fleet index)
};
struct FleetPlan {
  std::vector<Subgroup> subgroups;
};

// An explorer at its meeting with the station.
struct Report {
  int32_t box = -1;
  bool boxFinished = false;    // explored, and every feature found in it handed out
  double remaining = 0.0;      // s, predicted time to finish the box (eq. 9)
  uint32_t meetingNumber = 0;  // which meeting this is (the station answers each one once)
  double energy = 1.0;         // battery level (fraction; 1 when not limited): it charges first
  // The unknown workspace: the box's octree parts that still hold work (fleet_plan.h,
  // octreeChildren), when it is not finished and larger than a leaf. World-aligned (the
  // rotation is not sent).
  std::vector<agent::BoxView> remainder;
};

// An inspector whose explorer is presumed lost, and where it should be waiting.
struct Adoption {
  uint32_t inspector = 0;
  Vec3 place = Vec3::Zero();
};

// The station's answer: the box to work on (the same one, a new one, or -1: none left) and the
// next meeting.
struct Reply {
  uint32_t meetingNumber = 0;
  int32_t box = -1;
  Meeting next;
  // The station's meetings in the order it will serve them, this explorer's next included: an
  // explorer done early can catch the station at an earlier one (the station answers a report
  // whenever they are linked).
  std::vector<Meeting> stops;
  // Inspectors of a lost explorer to take into this explorer's subgroup, each with where it is
  // expected to wait (the station's prediction); `place` is the inspector's wait point.
  std::vector<Adoption> adopt;
  // The explorer had been presumed lost and its inspectors given to others: it forgets them.
  bool dropInspectors = false;
  // [energy]: when the station's charger is free for it (another explorer may be charging).
  double chargeFrom = 0.0;
  // The shape of `box` when it is a part the station made (world-aligned): the unknown
  // workspace's, or of a box split to share its work.
  std::optional<agent::BoxView> boxShape;
  // The subgroup's next box, reserved for it (-1: none): it goes on to it when done with `box`
  // before the next meeting, and says so in its report.
  int32_t nextBox = -1;
  std::optional<agent::BoxView> nextBoxShape;  // as boxShape, of `nextBox`
};

// An explorer's orders to one of its inspectors: features appended to its list in order, and
// optionally a place to go and wait once the list is done (a new box's corner).
struct Orders {
  uint32_t sequence = 0;  // increases per inspector; a repeat is ignored
  std::vector<FeatureTask> tasks;
  std::optional<Vec3> waitAt;
};

// An inspector to its explorer (who also sees where it is): the last orders it took and which
// features it has inspected so far.
struct Status {
  uint32_t lastOrders = 0;  // the sequence of the last orders it took (0: none)
  std::vector<uint32_t> inspected;
  uint32_t listLeft = 0;  // features still on its list (0: done with it)
};

std::vector<uint8_t> encode(const FleetPlan& plan);
std::vector<uint8_t> encode(const Report& report);
std::vector<uint8_t> encode(const Reply& reply);
std::vector<uint8_t> encode(const Orders& orders);
std::vector<uint8_t> encode(const Status& status);

std::optional<FleetPlan> decodePlan(const std::vector<uint8_t>& bytes);
std::optional<Report> decodeReport(const std::vector<uint8_t>& bytes);
std::optional<Reply> decodeReply(const std::vector<uint8_t>& bytes);
std::optional<Orders> decodeOrders(const std::vector<uint8_t>& bytes);
std::optional<Status> decodeStatus(const std::vector<uint8_t>& bytes);

}  // namespace coinspect::strategies::slei
