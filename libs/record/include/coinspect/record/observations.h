// Project observation classes for coinspect rawlogs: what MRPT has no class for (gimbal state,
// captures with their scored points, link topology changes, messages, mission events, ground
// station tally updates). They live in the shared library coinspect_record_types, which
// registers them with MRPT's RTTI when loaded, so `rawlog-edit -p <lib>` and
// `RawLogViewer -l <lib>` can read coinspect rawlogs. Layout and versions: doc/recording.md.
//
// Every class serializes timestamp and sensorLabel first (CObservation does not do it for its
// subclasses), then its own fields. Changing a class's fields means bumping its version and
// keeping the old versions readable: never change what an existing version number means.
#pragma once

#include <mrpt/obs/CObservation.h>
#include <mrpt/serialization/CSerializable.h>

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace coinspect::record {

// Registers the classes below with MRPT's RTTI. The library's load-time initialiser already
// calls it (that is how MRPT plugins work); calling it again is harmless.
void registerObservationClasses();

// A rigid pose in the world frame: position (m) and unit quaternion (w, x, y, z).
struct PoseRecord {
  std::array<double, 3> position{0.0, 0.0, 0.0};
  std::array<double, 4> quaternion{1.0, 0.0, 0.0, 0.0};
  bool operator==(const PoseRecord& other) const {
    return position == other.position && quaternion == other.quaternion;
  }
};

// Gimbal angles relative to the stabilizer frame (rad) and their rates (rad/s).
class CObservationCoinspectGimbal : public mrpt::obs::CObservation {
  DEFINE_SERIALIZABLE(CObservationCoinspectGimbal, coinspect::record)

 public:
  double yaw = 0.0;
  double pitch = 0.0;
  double yawRate = 0.0;
  double pitchRate = 0.0;

  void getSensorPose(mrpt::poses::CPose3D& out) const override;
  void setSensorPose(const mrpt::poses::CPose3D&) override {}
  void getDescriptionAsText(std::ostream& o) const override;
};

// One interest point scored by a capture (sensing::PointScore, reduced to what a replay needs).
struct ScoredPointRecord {
  uint32_t index = 0;
  bool seen = false;
  uint8_t notSeenReason = 0;  // sensing::NotSeenReason as its integer value (0 = None)
  double qBlur = 0.0;
  double qRes = 0.0;
  double score = 0.0;
  bool counted = false;
  bool operator==(const ScoredPointRecord& o) const {
    return index == o.index && seen == o.seen && notSeenReason == o.notSeenReason &&
           qBlur == o.qBlur && qRes == o.qRes && score == o.score && counted == o.counted;
  }
};

// Another UAV as the scorer saw it at a capture: a sphere that blocks the camera's rays.
struct OccluderRecord {
  std::array<double, 3> center{0.0, 0.0, 0.0};  // world frame, m
  double radius = 0.0;                          // m
  bool operator==(const OccluderRecord& o) const {
    return center == o.center && radius == o.radius;
  }
};

// One camera capture: where the camera was, how it moved, and the points it scored.
// Version 1 adds the body state exactly as the scorer received it (position and Z-Y-X Euler
// angles, bit for bit) and the occluding UAVs, so that `coinspect eval` can score the capture
// again and reproduce the live score exactly. Version 0 files read with hasBodyState = false.
class CObservationCoinspectCapture : public mrpt::obs::CObservation {
  DEFINE_SERIALIZABLE(CObservationCoinspectCapture, coinspect::record)

 public:
  PoseRecord cameraPose;                           // camera in the world
  std::array<double, 3> linearVelocity{0, 0, 0};   // body, world frame, m/s
  std::array<double, 3> angularVelocity{0, 0, 0};  // body frame, rad/s
  double gimbalYaw = 0.0;
  double gimbalPitch = 0.0;
  double gimbalYawRate = 0.0;
  double gimbalPitchRate = 0.0;
  std::vector<ScoredPointRecord> points;
  // Version 1.
  bool hasBodyState = true;                     // false when read from a version 0 object
  std::array<double, 3> bodyPosition{0, 0, 0};  // body origin in the world, m
  double bodyYaw = 0.0;                         // rad, R_WB = Rz(yaw) Ry(pitch) Rx(roll)
  double bodyPitch = 0.0;
  double bodyRoll = 0.0;
  std::vector<OccluderRecord> occluders;

  void getSensorPose(mrpt::poses::CPose3D& out) const override;
  void setSensorPose(const mrpt::poses::CPose3D&) override {}
  void getDescriptionAsText(std::ostream& o) const override;
};

// A line-of-sight link between two units that appeared (linked) or disappeared.
struct LinkChangeRecord {
  std::string unitA;
  std::string unitB;
  bool linked = false;
  bool operator==(const LinkChangeRecord& o) const {
    return unitA == o.unitA && unitB == o.unitB && linked == o.linked;
  }
};

// The link pairs whose state changed at one tick.
class CObservationCoinspectLinks : public mrpt::obs::CObservation {
  DEFINE_SERIALIZABLE(CObservationCoinspectLinks, coinspect::record)

 public:
  std::vector<LinkChangeRecord> changes;

  void getSensorPose(mrpt::poses::CPose3D& out) const override;
  void setSensorPose(const mrpt::poses::CPose3D&) override {}
  void getDescriptionAsText(std::ostream& o) const override;
};

// One message between units, with its size and fate.
struct MessageRecord {
  std::string from;
  std::string to;
  std::string topic;
  uint64_t bytes = 0;
  bool delivered = false;  // false = dropped
  bool operator==(const MessageRecord& o) const {
    return from == o.from && to == o.to && topic == o.topic && bytes == o.bytes &&
           delivered == o.delivered;
  }
};

// The messages sent at one tick.
class CObservationCoinspectMessages : public mrpt::obs::CObservation {
  DEFINE_SERIALIZABLE(CObservationCoinspectMessages, coinspect::record)

 public:
  std::vector<MessageRecord> messages;

  void getSensorPose(mrpt::poses::CPose3D& out) const override;
  void setSensorPose(const mrpt::poses::CPose3D&) override {}
  void getDescriptionAsText(std::ostream& o) const override;
};

// Stored as uint8: append new kinds, never renumber (the evaluator reads these numbers).
enum class MissionEventKind : uint8_t {
  Start = 0,
  End = 1,
  Collision = 2,
  Failure = 3,  // an injected fault
  Death = 4,    // a unit stops working (collision, fault): `coinspect eval` tracks alive flags
  NoTakeoff = 5,
  BlackoutStart = 6,
  BlackoutEnd = 7,
  RecordingFailed = 8,  // the recorder could not write; the mission was stopped
  // Feature missions (doc/features.md); detail "feature <index>" or, for a meeting, the other unit.
  FeatureDetected = 9,    // the first detection of a feature by any explorer
  FeatureInspected = 10,  // an inspector completed a feature's inspection
  FeatureCollected = 11,  // the ground station received a feature's inspection result
  Meeting = 12,           // two units linked again after a gap (unit: the lower fleet index)
  // A unit's reported activity (agent::toString(Activity), e.g. "exploring") from now on: each
  // unit's activity at the start of the mission clock, then every change while it is alive.
  ActivityChanged = 13,
  // [energy]: a UAV starts / stops charging at a station; detail: its level ("35 %").
  ChargeStart = 14,
  ChargeEnd = 15,
};
// The last kind this build knows (readers reject larger values).
inline constexpr MissionEventKind kLastMissionEventKind = MissionEventKind::ChargeEnd;
const char* toString(MissionEventKind kind);

// A mission event: start, end, no take-off, a unit's collision, failure or death, blackouts.
class CObservationCoinspectEvent : public mrpt::obs::CObservation {
  DEFINE_SERIALIZABLE(CObservationCoinspectEvent, coinspect::record)

 public:
  MissionEventKind kind = MissionEventKind::Start;
  std::string unit;    // empty for mission-wide events
  std::string detail;  // free text for people

  void getSensorPose(mrpt::poses::CPose3D& out) const override;
  void setSensorPose(const mrpt::poses::CPose3D&) override {}
  void getDescriptionAsText(std::ostream& o) const override;
};

// One interest point whose ground-station value improved.
struct TallyChangeRecord {
  uint32_t index = 0;
  double value = 0.0;
  bool operator==(const TallyChangeRecord& o) const { return index == o.index && value == o.value; }
};

// A ground-station tally update: the improved points and the totals after it.
class CObservationCoinspectTally : public mrpt::obs::CObservation {
  DEFINE_SERIALIZABLE(CObservationCoinspectTally, coinspect::record)

 public:
  std::vector<TallyChangeRecord> changes;
  uint64_t detected = 0;    // points counted by the ground station after this update
  uint64_t pointCount = 0;  // interest points in the scenario
  double totalScore = 0.0;  // sum of the tally's values

  void getSensorPose(mrpt::poses::CPose3D& out) const override;
  void setSensorPose(const mrpt::poses::CPose3D&) override {}
  void getDescriptionAsText(std::ostream& o) const override;
};

}  // namespace coinspect::record
