// Every project observation class survives MRPT serialization field by field, and is known to
// MRPT's RTTI by its full name (what rawlog-edit looks up when it reads a rawlog).
#include <gtest/gtest.h>
#include <mrpt/core/Clock.h>
#include <mrpt/io/CMemoryStream.h>
#include <mrpt/rtti/CObject.h>
#include <mrpt/serialization/CArchive.h>

#include <algorithm>
#include <sstream>
#include <utility>
#include <vector>

#include "coinspect/record/observations.h"

namespace coinspect::record {
namespace {

// Serializes `original` into memory and reads it back as a new object of the same class.
template <typename T>
std::shared_ptr<T> roundTrip(const T& original) {
  mrpt::io::CMemoryStream buffer;
  auto archive = mrpt::serialization::archiveFrom(buffer);
  archive << original;
  buffer.Seek(0);
  auto copy = std::dynamic_pointer_cast<T>(archive.ReadObject());
  EXPECT_TRUE(copy) << "read back as another class";
  EXPECT_EQ(buffer.getPosition(), buffer.getTotalBytesCount()) << "bytes left unread";
  return copy;
}

template <typename T>
void setCommon(T& o, const char* label, double time) {
  o.sensorLabel = label;
  o.timestamp = mrpt::Clock::fromDouble(time);
}

template <typename T>
void expectCommon(const T& a, const T& b) {
  EXPECT_EQ(a.sensorLabel, b.sensorLabel);
  EXPECT_EQ(a.timestamp, b.timestamp);
}

TEST(Observations, GimbalRoundTrips) {
  CObservationCoinspectGimbal o;
  setCommon(o, "jurong.gimbal", 12.25);
  o.yaw = 0.5;
  o.pitch = -0.25;
  o.yawRate = 1.5;
  o.pitchRate = -2.0;
  const auto c = roundTrip(o);
  ASSERT_TRUE(c);
  expectCommon(o, *c);
  EXPECT_EQ(c->yaw, 0.5);
  EXPECT_EQ(c->pitch, -0.25);
  EXPECT_EQ(c->yawRate, 1.5);
  EXPECT_EQ(c->pitchRate, -2.0);
}

TEST(Observations, CaptureRoundTrips) {
  CObservationCoinspectCapture o;
  setCommon(o, "sentosa.camera", 3.5);
  o.cameraPose.position = {1.0, -2.0, 3.0};
  o.cameraPose.quaternion = {0.5, 0.5, -0.5, 0.5};
  o.linearVelocity = {0.1, 0.2, 0.3};
  o.angularVelocity = {-0.1, -0.2, -0.3};
  o.gimbalYaw = 0.7;
  o.gimbalPitch = -0.3;
  o.gimbalYawRate = 0.05;
  o.gimbalPitchRate = -0.05;
  o.points = {{7, true, 0, 0.9, 0.8, 0.72, true}, {9, false, 3, 0.0, 0.0, 0.0, false}};
  o.bodyPosition = {1.0, -2.0, 2.875};
  o.bodyYaw = 0.125;
  o.bodyPitch = -0.0625;
  o.bodyRoll = 0.03125;
  o.occluders = {{{4.0, 5.0, 6.0}, 0.5}, {{-1.0, 0.0, 2.0}, 0.25}};
  const auto c = roundTrip(o);
  ASSERT_TRUE(c);
  expectCommon(o, *c);
  EXPECT_TRUE(c->hasBodyState);
  EXPECT_EQ(c->bodyPosition, o.bodyPosition);
  EXPECT_EQ(c->bodyYaw, 0.125);
  EXPECT_EQ(c->bodyPitch, -0.0625);
  EXPECT_EQ(c->bodyRoll, 0.03125);
  EXPECT_EQ(c->occluders, o.occluders);
  EXPECT_EQ(c->cameraPose, o.cameraPose);
  EXPECT_EQ(c->linearVelocity, o.linearVelocity);
  EXPECT_EQ(c->angularVelocity, o.angularVelocity);
  EXPECT_EQ(c->gimbalYaw, 0.7);
  EXPECT_EQ(c->gimbalPitch, -0.3);
  EXPECT_EQ(c->gimbalYawRate, 0.05);
  EXPECT_EQ(c->gimbalPitchRate, -0.05);
  EXPECT_EQ(c->points, o.points);
}

TEST(Observations, LinksRoundTrip) {
  CObservationCoinspectLinks o;
  setCommon(o, "gcs.links", 1.0);
  o.changes = {{"jurong", "gcs", true}, {"jurong", "raffles", false}};
  const auto c = roundTrip(o);
  ASSERT_TRUE(c);
  expectCommon(o, *c);
  EXPECT_EQ(c->changes, o.changes);
}

// A damaged boolean byte (here `linked`, the last field before MRPT's end flag) is refused: it
// once became a bool that was neither true nor false (UBSan: "not a valid value for type bool").
TEST(Observations, ABooleanByteOtherThanZeroOrOneIsDamage) {
  CObservationCoinspectLinks o;
  setCommon(o, "gcs.links", 1.0);
  o.changes = {{"jurong", "gcs", true}};
  mrpt::io::CMemoryStream buffer;
  auto archive = mrpt::serialization::archiveFrom(buffer);
  archive << o;
  auto* bytes = static_cast<uint8_t*>(buffer.getRawBufferData());
  const size_t linked = buffer.getTotalBytesCount() - 2;
  ASSERT_EQ(bytes[linked], 1u);
  bytes[linked] = 79;
  buffer.Seek(0);
  EXPECT_THROW(archive.ReadObject(), std::exception);
}

TEST(Observations, MessagesRoundTrip) {
  CObservationCoinspectMessages o;
  setCommon(o, "gcs.messages", 2.0);
  o.messages = {{"jurong", "gcs", "map", 123456, true}, {"sentosa", "jurong", "plan", 42, false}};
  const auto c = roundTrip(o);
  ASSERT_TRUE(c);
  expectCommon(o, *c);
  EXPECT_EQ(c->messages, o.messages);
}

TEST(Observations, EventRoundTrips) {
  CObservationCoinspectEvent o;
  setCommon(o, "raffles.event", 99.0);
  o.kind = MissionEventKind::Collision;
  o.unit = "raffles";
  o.detail = "hit the building at 3 m/s";
  const auto c = roundTrip(o);
  ASSERT_TRUE(c);
  expectCommon(o, *c);
  EXPECT_EQ(c->kind, MissionEventKind::Collision);
  EXPECT_EQ(c->unit, o.unit);
  EXPECT_EQ(c->detail, o.detail);
}

// The numbers are part of the format (the evaluator and old files rely on them): appended only.
TEST(Observations, EventKindsKeepTheirNumbersAndRoundTrip) {
  const std::vector<std::pair<MissionEventKind, const char*>> kinds = {
      {MissionEventKind::Start, "mission-start"},
      {MissionEventKind::End, "mission-end"},
      {MissionEventKind::Collision, "collision"},
      {MissionEventKind::Failure, "fault"},
      {MissionEventKind::Death, "death"},
      {MissionEventKind::NoTakeoff, "no-takeoff"},
      {MissionEventKind::BlackoutStart, "blackout-start"},
      {MissionEventKind::BlackoutEnd, "blackout-end"},
      {MissionEventKind::RecordingFailed, "recording-failed"},
      {MissionEventKind::FeatureDetected, "feature-detected"},
      {MissionEventKind::FeatureInspected, "feature-inspected"},
      {MissionEventKind::FeatureCollected, "feature-collected"},
      {MissionEventKind::Meeting, "meeting"},
      {MissionEventKind::ActivityChanged, "activity-changed"},
      {MissionEventKind::ChargeStart, "charge-start"},
      {MissionEventKind::ChargeEnd, "charge-end"}};
  for (size_t number = 0; number < kinds.size(); ++number) {
    const auto [kind, name] = kinds[number];
    EXPECT_EQ(static_cast<size_t>(kind), number) << name;
    EXPECT_STREQ(toString(kind), name);
    CObservationCoinspectEvent o;
    setCommon(o, "mission.event", 1.0);
    o.kind = kind;
    const auto c = roundTrip(o);
    ASSERT_TRUE(c);
    EXPECT_EQ(c->kind, kind);
  }
  EXPECT_EQ(kLastMissionEventKind, kinds.back().first);
}

TEST(Observations, TallyRoundTrips) {
  CObservationCoinspectTally o;
  setCommon(o, "gcs.tally", 4.0);
  o.changes = {{3, 0.25}, {11, 0.875}};
  o.detected = 2;
  o.pointCount = 50;
  o.totalScore = 1.125;
  const auto c = roundTrip(o);
  ASSERT_TRUE(c);
  expectCommon(o, *c);
  EXPECT_EQ(c->changes, o.changes);
  EXPECT_EQ(c->detected, 2u);
  EXPECT_EQ(c->pointCount, 50u);
  EXPECT_EQ(c->totalScore, 1.125);
}

// A version 0 capture (written before the body state and occluders were added) still reads:
// its bytes are a version 1 object without the appended fields and with version byte 0.
TEST(Observations, CaptureVersion0StillReads) {
  CObservationCoinspectCapture o;
  setCommon(o, "sentosa.camera", 2.0);
  o.gimbalPitch = -0.5;
  o.points = {{3, true, 0, 1.0, 0.5, 0.5, true}};
  mrpt::io::CMemoryStream buffer;
  auto archive = mrpt::serialization::archiveFrom(buffer);
  archive << o;
  const auto* begin = static_cast<const uint8_t*>(buffer.getRawBufferData());
  std::vector<uint8_t> bytes(begin, begin + buffer.getTotalBytesCount());
  const std::string name = "coinspect::record::CObservationCoinspectCapture";
  const auto at = std::search(bytes.begin(), bytes.end(), name.begin(), name.end());
  ASSERT_NE(at, bytes.end());
  const auto versionByte = at + static_cast<std::ptrdiff_t>(name.size());
  ASSERT_EQ(*versionByte, 1);
  *versionByte = 0;
  // Version 1 appended 3 + 3 doubles and an occluder count before the end-of-object marker.
  const size_t appended = 6 * sizeof(double) + sizeof(uint32_t);
  bytes.erase(bytes.end() - 1 - static_cast<std::ptrdiff_t>(appended), bytes.end() - 1);
  mrpt::io::CMemoryStream old;
  old.assignMemoryNotOwn(bytes.data(), bytes.size());
  auto oldArchive = mrpt::serialization::archiveFrom(old);
  const auto c = std::dynamic_pointer_cast<CObservationCoinspectCapture>(oldArchive.ReadObject());
  ASSERT_TRUE(c);
  EXPECT_EQ(old.getPosition(), bytes.size());
  EXPECT_FALSE(c->hasBodyState);
  EXPECT_EQ(c->gimbalPitch, -0.5);
  EXPECT_EQ(c->points, o.points);
  EXPECT_TRUE(c->occluders.empty());
}

TEST(Observations, EmptyListsRoundTrip) {
  CObservationCoinspectCapture o;
  setCommon(o, "a.camera", 0.0);
  const auto c = roundTrip(o);
  ASSERT_TRUE(c);
  EXPECT_TRUE(c->points.empty());
}

TEST(Observations, ClassesAreRegisteredByFullName) {
  registerObservationClasses();
  for (const char* name : {"coinspect::record::CObservationCoinspectGimbal",
                           "coinspect::record::CObservationCoinspectCapture",
                           "coinspect::record::CObservationCoinspectLinks",
                           "coinspect::record::CObservationCoinspectMessages",
                           "coinspect::record::CObservationCoinspectEvent",
                           "coinspect::record::CObservationCoinspectTally"})
    EXPECT_NE(mrpt::rtti::findRegisteredClass(name), nullptr) << name;
}

TEST(Observations, DescriptionNamesTheContent) {
  CObservationCoinspectEvent o;
  setCommon(o, "mission.event", 0.0);
  o.kind = MissionEventKind::Failure;
  o.detail = "battery";
  std::ostringstream text;
  o.getDescriptionAsText(text);
  EXPECT_NE(text.str().find("fault"), std::string::npos) << text.str();
  EXPECT_NE(text.str().find("battery"), std::string::npos) << text.str();
}

}  // namespace
}  // namespace coinspect::record
