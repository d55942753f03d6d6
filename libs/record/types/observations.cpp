// Serialization of the project observation classes. Every class is at version 0 except the
// capture (version 1, which appends fields to version 0). A new layout gets a new version, and
// serializeFrom keeps reading the old ones.
#include "coinspect/record/observations.h"

#include <mrpt/core/exceptions.h>
#include <mrpt/core/initializer.h>
#include <mrpt/poses/CPose3D.h>
#include <mrpt/serialization/CArchive.h>

#include <ostream>
#include <stdexcept>
#include <string>

using mrpt::serialization::CArchive;

namespace coinspect::record {
namespace {

// Element counts are written as uint32. Reading appends one element at a time (no reserve),
// so a damaged count runs into the end of the stream instead of a huge allocation.
template <typename T, typename WriteOne>
void writeVector(CArchive& out, const std::vector<T>& items, WriteOne writeOne) {
  out.WriteAs<uint32_t>(items.size());
  for (const auto& item : items)
    writeOne(item);
}

template <typename T, typename ReadOne>
void readVector(CArchive& in, std::vector<T>& items, ReadOne readOne) {
  const auto count = in.ReadAs<uint32_t>();
  items.clear();
  for (uint32_t i = 0; i < count; ++i) {
    T item;
    readOne(item);
    items.push_back(std::move(item));
  }
}

// MRPT reads a bool straight into its byte, so a damaged byte other than 0 or 1 became a bool
// that is neither (undefined behaviour; found by fuzzing `coinspect eval` under UBSan). Read the
// byte (MRPT writes true as 1) and refuse the others: the reader reports the damage there.
bool readBool(CArchive& in) {
  const auto byte = in.ReadAs<uint8_t>();
  if (byte > 1) throw std::runtime_error("a boolean field holds the byte " + std::to_string(byte));
  return byte == 1;
}

template <size_t N>
void writeArray(CArchive& out, const std::array<double, N>& values) {
  for (double v : values)
    out << v;
}

template <size_t N>
void readArray(CArchive& in, std::array<double, N>& values) {
  for (double& v : values)
    in >> v;
}

void writeCommon(CArchive& out, const mrpt::obs::CObservation& o) {
  out << o.timestamp << o.sensorLabel;
}

void readCommon(CArchive& in, mrpt::obs::CObservation& o) {
  in >> o.timestamp >> o.sensorLabel;
}

void writePose(CArchive& out, const PoseRecord& pose) {
  writeArray(out, pose.position);
  writeArray(out, pose.quaternion);
}

void readPose(CArchive& in, PoseRecord& pose) {
  readArray(in, pose.position);
  readArray(in, pose.quaternion);
}

}  // namespace

// --- Gimbal -------------------------------------------------------------------------------
uint8_t CObservationCoinspectGimbal::serializeGetVersion() const {
  return 0;
}

void CObservationCoinspectGimbal::serializeTo(CArchive& out) const {
  writeCommon(out, *this);
  out << yaw << pitch << yawRate << pitchRate;
}

void CObservationCoinspectGimbal::serializeFrom(CArchive& in, uint8_t version) {
  switch (version) {
    case 0:
      readCommon(in, *this);
      in >> yaw >> pitch >> yawRate >> pitchRate;
      break;
    default:
      MRPT_THROW_UNKNOWN_SERIALIZATION_VERSION(version);
  }
}

void CObservationCoinspectGimbal::getSensorPose(mrpt::poses::CPose3D& out) const {
  out = mrpt::poses::CPose3D();
}

void CObservationCoinspectGimbal::getDescriptionAsText(std::ostream& o) const {
  CObservation::getDescriptionAsText(o);
  o << "coinspect gimbal state\n"
    << "yaw " << yaw << " rad, pitch " << pitch << " rad\n"
    << "yaw rate " << yawRate << " rad/s, pitch rate " << pitchRate << " rad/s\n";
}

// --- Capture ------------------------------------------------------------------------------
uint8_t CObservationCoinspectCapture::serializeGetVersion() const {
  return 1;
}

void CObservationCoinspectCapture::serializeTo(CArchive& out) const {
  writeCommon(out, *this);
  writePose(out, cameraPose);
  writeArray(out, linearVelocity);
  writeArray(out, angularVelocity);
  out << gimbalYaw << gimbalPitch << gimbalYawRate << gimbalPitchRate;
  writeVector(out, points, [&](const ScoredPointRecord& p) {
    out << p.index << p.seen << p.notSeenReason << p.qBlur << p.qRes << p.score << p.counted;
  });
  // Version 1.
  writeArray(out, bodyPosition);
  out << bodyYaw << bodyPitch << bodyRoll;
  writeVector(out, occluders, [&](const OccluderRecord& o) {
    writeArray(out, o.center);
    out << o.radius;
  });
}

void CObservationCoinspectCapture::serializeFrom(CArchive& in, uint8_t version) {
  if (version > 1) MRPT_THROW_UNKNOWN_SERIALIZATION_VERSION(version);
  // Version 1 appends fields to version 0's layout.
  readCommon(in, *this);
  readPose(in, cameraPose);
  readArray(in, linearVelocity);
  readArray(in, angularVelocity);
  in >> gimbalYaw >> gimbalPitch >> gimbalYawRate >> gimbalPitchRate;
  readVector(in, points, [&](ScoredPointRecord& p) {
    in >> p.index;
    p.seen = readBool(in);
    in >> p.notSeenReason >> p.qBlur >> p.qRes >> p.score;
    p.counted = readBool(in);
  });
  hasBodyState = version >= 1;
  bodyPosition = {0.0, 0.0, 0.0};
  bodyYaw = bodyPitch = bodyRoll = 0.0;
  occluders.clear();
  if (version == 0) return;
  readArray(in, bodyPosition);
  in >> bodyYaw >> bodyPitch >> bodyRoll;
  readVector(in, occluders, [&](OccluderRecord& o) {
    readArray(in, o.center);
    in >> o.radius;
  });
}

void CObservationCoinspectCapture::getSensorPose(mrpt::poses::CPose3D& out) const {
  // The camera pose is absolute (world frame): there is no body-relative sensor pose.
  out = mrpt::poses::CPose3D();
}

void CObservationCoinspectCapture::getDescriptionAsText(std::ostream& o) const {
  CObservation::getDescriptionAsText(o);
  const auto& p = cameraPose.position;
  const auto& q = cameraPose.quaternion;
  o << "coinspect capture\n"
    << "camera position " << p[0] << " " << p[1] << " " << p[2] << " m\n"
    << "camera quaternion (w x y z) " << q[0] << " " << q[1] << " " << q[2] << " " << q[3] << "\n"
    << "linear velocity " << linearVelocity[0] << " " << linearVelocity[1] << " "
    << linearVelocity[2] << " m/s\n"
    << "angular velocity " << angularVelocity[0] << " " << angularVelocity[1] << " "
    << angularVelocity[2] << " rad/s\n"
    << "gimbal yaw " << gimbalYaw << " pitch " << gimbalPitch << " rad, rates " << gimbalYawRate
    << " " << gimbalPitchRate << " rad/s\n"
    << points.size() << " scored points (index seen reason q_blur q_res score counted):\n";
  if (hasBodyState)
    o << "body position " << bodyPosition[0] << " " << bodyPosition[1] << " " << bodyPosition[2]
      << " m, yaw " << bodyYaw << " pitch " << bodyPitch << " roll " << bodyRoll << " rad, "
      << occluders.size() << " occluding UAVs\n";
  for (const auto& s : points)
    o << "  " << s.index << " " << s.seen << " " << int(s.notSeenReason) << " " << s.qBlur << " "
      << s.qRes << " " << s.score << " " << s.counted << "\n";
}

// --- Links --------------------------------------------------------------------------------
uint8_t CObservationCoinspectLinks::serializeGetVersion() const {
  return 0;
}

void CObservationCoinspectLinks::serializeTo(CArchive& out) const {
  writeCommon(out, *this);
  writeVector(out, changes,
              [&](const LinkChangeRecord& c) { out << c.unitA << c.unitB << c.linked; });
}

void CObservationCoinspectLinks::serializeFrom(CArchive& in, uint8_t version) {
  switch (version) {
    case 0:
      readCommon(in, *this);
      readVector(in, changes, [&](LinkChangeRecord& c) {
        in >> c.unitA >> c.unitB;
        c.linked = readBool(in);
      });
      break;
    default:
      MRPT_THROW_UNKNOWN_SERIALIZATION_VERSION(version);
  }
}

void CObservationCoinspectLinks::getSensorPose(mrpt::poses::CPose3D& out) const {
  out = mrpt::poses::CPose3D();
}

void CObservationCoinspectLinks::getDescriptionAsText(std::ostream& o) const {
  CObservation::getDescriptionAsText(o);
  o << "coinspect link changes: " << changes.size() << "\n";
  for (const auto& c : changes)
    o << "  " << c.unitA << " - " << c.unitB << (c.linked ? " linked" : " unlinked") << "\n";
}

// --- Messages -----------------------------------------------------------------------------
uint8_t CObservationCoinspectMessages::serializeGetVersion() const {
  return 0;
}

void CObservationCoinspectMessages::serializeTo(CArchive& out) const {
  writeCommon(out, *this);
  writeVector(out, messages, [&](const MessageRecord& m) {
    out << m.from << m.to << m.topic << m.bytes << m.delivered;
  });
}

void CObservationCoinspectMessages::serializeFrom(CArchive& in, uint8_t version) {
  switch (version) {
    case 0:
      readCommon(in, *this);
      readVector(in, messages, [&](MessageRecord& m) {
        in >> m.from >> m.to >> m.topic >> m.bytes;
        m.delivered = readBool(in);
      });
      break;
    default:
      MRPT_THROW_UNKNOWN_SERIALIZATION_VERSION(version);
  }
}

void CObservationCoinspectMessages::getSensorPose(mrpt::poses::CPose3D& out) const {
  out = mrpt::poses::CPose3D();
}

void CObservationCoinspectMessages::getDescriptionAsText(std::ostream& o) const {
  CObservation::getDescriptionAsText(o);
  o << "coinspect messages: " << messages.size() << "\n";
  for (const auto& m : messages)
    o << "  " << m.from << " -> " << m.to << " [" << m.topic << "] " << m.bytes << " bytes "
      << (m.delivered ? "delivered" : "dropped") << "\n";
}

// --- Events -------------------------------------------------------------------------------
const char* toString(MissionEventKind kind) {
  switch (kind) {
    case MissionEventKind::Start:
      return "mission-start";
    case MissionEventKind::End:
      return "mission-end";
    case MissionEventKind::Collision:
      return "collision";
    case MissionEventKind::Failure:
      return "fault";
    case MissionEventKind::Death:
      return "death";
    case MissionEventKind::NoTakeoff:
      return "no-takeoff";
    case MissionEventKind::BlackoutStart:
      return "blackout-start";
    case MissionEventKind::BlackoutEnd:
      return "blackout-end";
    case MissionEventKind::RecordingFailed:
      return "recording-failed";
    case MissionEventKind::FeatureDetected:
      return "feature-detected";
    case MissionEventKind::FeatureInspected:
      return "feature-inspected";
    case MissionEventKind::FeatureCollected:
      return "feature-collected";
    case MissionEventKind::Meeting:
      return "meeting";
    case MissionEventKind::ActivityChanged:
      return "activity-changed";
    case MissionEventKind::ChargeStart:
      return "charge-start";
    case MissionEventKind::ChargeEnd:
      return "charge-end";
  }
  return "unknown";
}

uint8_t CObservationCoinspectEvent::serializeGetVersion() const {
  return 0;
}

void CObservationCoinspectEvent::serializeTo(CArchive& out) const {
  writeCommon(out, *this);
  out << static_cast<uint8_t>(kind) << unit << detail;
}

void CObservationCoinspectEvent::serializeFrom(CArchive& in, uint8_t version) {
  switch (version) {
    case 0: {
      readCommon(in, *this);
      uint8_t rawKind = 0;
      in >> rawKind >> unit >> detail;
      ASSERTMSG_(rawKind <= static_cast<uint8_t>(kLastMissionEventKind),
                 "unknown coinspect mission event kind");
      kind = static_cast<MissionEventKind>(rawKind);
      break;
    }
    default:
      MRPT_THROW_UNKNOWN_SERIALIZATION_VERSION(version);
  }
}

void CObservationCoinspectEvent::getSensorPose(mrpt::poses::CPose3D& out) const {
  out = mrpt::poses::CPose3D();
}

void CObservationCoinspectEvent::getDescriptionAsText(std::ostream& o) const {
  CObservation::getDescriptionAsText(o);
  o << "coinspect mission event: " << toString(kind) << (unit.empty() ? "" : " unit ") << unit
    << "\n"
    << detail << "\n";
}

// --- Tally --------------------------------------------------------------------------------
uint8_t CObservationCoinspectTally::serializeGetVersion() const {
  return 0;
}

void CObservationCoinspectTally::serializeTo(CArchive& out) const {
  writeCommon(out, *this);
  writeVector(out, changes, [&](const TallyChangeRecord& c) { out << c.index << c.value; });
  out << detected << pointCount << totalScore;
}

void CObservationCoinspectTally::serializeFrom(CArchive& in, uint8_t version) {
  switch (version) {
    case 0:
      readCommon(in, *this);
      readVector(in, changes, [&](TallyChangeRecord& c) { in >> c.index >> c.value; });
      in >> detected >> pointCount >> totalScore;
      break;
    default:
      MRPT_THROW_UNKNOWN_SERIALIZATION_VERSION(version);
  }
}

void CObservationCoinspectTally::getSensorPose(mrpt::poses::CPose3D& out) const {
  out = mrpt::poses::CPose3D();
}

void CObservationCoinspectTally::getDescriptionAsText(std::ostream& o) const {
  CObservation::getDescriptionAsText(o);
  o << "coinspect ground station tally: " << detected << " of " << pointCount
    << " points detected, total score " << totalScore << "\n"
    << changes.size() << " improved points (index value):\n";
  for (const auto& c : changes)
    o << "  " << c.index << " " << c.value << "\n";
}

// --- RTTI ---------------------------------------------------------------------------------
void registerObservationClasses() {
  using namespace mrpt::rtti;
  registerClass(CLASS_ID(CObservationCoinspectGimbal));
  registerClass(CLASS_ID(CObservationCoinspectCapture));
  registerClass(CLASS_ID(CObservationCoinspectLinks));
  registerClass(CLASS_ID(CObservationCoinspectMessages));
  registerClass(CLASS_ID(CObservationCoinspectEvent));
  registerClass(CLASS_ID(CObservationCoinspectTally));
}

}  // namespace coinspect::record

IMPLEMENTS_SERIALIZABLE(CObservationCoinspectGimbal, CObservation, coinspect::record)
IMPLEMENTS_SERIALIZABLE(CObservationCoinspectCapture, CObservation, coinspect::record)
IMPLEMENTS_SERIALIZABLE(CObservationCoinspectLinks, CObservation, coinspect::record)
IMPLEMENTS_SERIALIZABLE(CObservationCoinspectMessages, CObservation, coinspect::record)
IMPLEMENTS_SERIALIZABLE(CObservationCoinspectEvent, CObservation, coinspect::record)
IMPLEMENTS_SERIALIZABLE(CObservationCoinspectTally, CObservation, coinspect::record)

// MRPT loads plugin classes by dlopen'ing the library (rawlog-edit -p, RawLogViewer -l): the
// classes must register themselves at load time, the one accepted static initialiser here.
MRPT_INITIALIZER(registerCoinspectRecordClasses) {
  coinspect::record::registerObservationClasses();
}
