#include "coinspect/eval/run_tracks.h"

#include <gtest/gtest.h>

#include <limits>

#include "coinspect/core/error.h"
#include "coinspect/record/observations.h"
#include "coinspect/record/rawlog_writer.h"
#include "coinspect/testing/files.h"
#include "coinspect/testing/input_errors.h"
#include "coinspect/testing/paths.h"
#include "picture_run.h"

namespace coinspect::eval {
namespace {

using record::MissionEventKind;

TEST(RunTracks, ReadsPosesTallyAndEventsOfARun) {
  const auto dir = testing::scratchDir("run_tracks_reads");
  test::writePictureRun(dir / "run.rawlog");
  const RunTracks tracks = readRunTracks(dir / "run.rawlog");

  EXPECT_TRUE(tracks.status.clean) << tracks.status.message;
  EXPECT_EQ(tracks.header.seed, 7u);
  ASSERT_EQ(tracks.units.size(), 3u);
  EXPECT_EQ(tracks.units[0].name, "gcs");
  EXPECT_EQ(tracks.units[1].name, "alpha");
  EXPECT_EQ(tracks.units[2].name, "bravo");
  for (const auto& unit : tracks.units)
    EXPECT_EQ(unit.poses.size(), 241u) << unit.name;
  const auto& alpha = tracks.units[1].poses;
  EXPECT_NEAR((alpha[60].position - test::alphaAt(3.0)).norm(), 0.0, 1e-9);
  EXPECT_DOUBLE_EQ(alpha[60].time, 3.0);
  EXPECT_NEAR(std::abs(alpha[60].yaw), M_PI, 1e-9);  // a quarter turn, heading along the circle
  EXPECT_DOUBLE_EQ(tracks.endTime, test::kEndTime);

  ASSERT_EQ(tracks.tally.size(), 3u);
  EXPECT_DOUBLE_EQ(tracks.tally[1].time, 4.0);
  EXPECT_DOUBLE_EQ(tracks.finalScore(), 1.75);
  EXPECT_EQ(tracks.finalDetected(), 3u);
  EXPECT_EQ(tracks.pointCount, 12u);
  ASSERT_EQ(tracks.finalValues.size(), 11u);  // up to point 10, the highest changed
  EXPECT_DOUBLE_EQ(tracks.finalValues[4], 1.0);
  EXPECT_DOUBLE_EQ(tracks.finalValues[0], 0.5);
  EXPECT_DOUBLE_EQ(tracks.finalValues[10], 0.25);
  EXPECT_DOUBLE_EQ(tracks.finalValues[1], 0.0);
  EXPECT_EQ(tracks.tallyChanges.size(), 3u);

  ASSERT_EQ(tracks.events.size(), 4u);
  EXPECT_EQ(tracks.events[0].kind, MissionEventKind::Start);
  EXPECT_DOUBLE_EQ(tracks.events[0].time, 0.5);
  EXPECT_EQ(tracks.events[1].kind, MissionEventKind::Collision);
  EXPECT_EQ(tracks.events[1].unit, "bravo");
  EXPECT_EQ(tracks.events[3].kind, MissionEventKind::End);
  EXPECT_FALSE(tracks.units[1].deathTime.has_value());
  ASSERT_TRUE(tracks.units[2].deathTime.has_value());
  EXPECT_DOUBLE_EQ(*tracks.units[2].deathTime, test::kBravoLost);
  EXPECT_EQ(tracks.units[2].deathCause, "collision: hit the cube");
}

TEST(RunTracks, ADamagedRawlogIsReadUpToTheDamage) {
  const auto dir = testing::scratchDir("run_tracks_damaged");
  test::writePictureRun(dir / "run.rawlog");
  const std::string bytes = testing::readFile(dir / "run.rawlog");
  testing::writeFile(dir / "cut.rawlog", bytes.substr(0, bytes.size() / 2));
  const RunTracks tracks = readRunTracks(dir / "cut.rawlog");
  EXPECT_FALSE(tracks.status.clean);
  EXPECT_NE(tracks.status.message.find("cut.rawlog"), std::string::npos) << tracks.status.message;
  EXPECT_NE(tracks.status.message.find("byte offset"), std::string::npos) << tracks.status.message;
  ASSERT_EQ(tracks.units.size(), 3u);
  EXPECT_GT(tracks.units[1].poses.size(), 10u);
  EXPECT_LT(tracks.units[1].poses.size(), 241u);
  EXPECT_EQ(tracks.objects, tracks.status.objects);
}

// Found by fuzzing the pictures: an infinite pose broke MRPT's projection with a raw MRPT
// exception, and a tally whose point count read 10^12 ran out of memory.
TEST(RunTracks, AnInfinitePoseIsAnInputErrorAndAHugePointCountAllocatesNothing) {
  const auto dir = testing::scratchDir("run_tracks_values");
  const auto write = [&](const std::string& name, double x, uint64_t pointCount) {
    record::RawlogWriter writer(dir / name, record::RunHeader{"0.1.0", 1, "00", ""}, 1.0);
    Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
    writer.writeGroundTruth("alpha", 0.0, pose, Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero());
    pose.translation().x() = x;
    writer.writeGroundTruth("alpha", 0.05, pose, Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero());
    writer.writeTally(0.05, {{3, 0.5}}, 1, pointCount, 0.5);
    writer.close();
    return dir / name;
  };
  const auto infinite = write("inf.rawlog", std::numeric_limits<double>::infinity(), 10);
  const std::string message = testing::messageOf([&] { readRunTracks(infinite); });
  EXPECT_MENTIONS(message, "inf.rawlog");
  EXPECT_MENTIONS(message, "alpha.pose at t = 0.05");
  EXPECT_MENTIONS(message, "the pose is not finite");

  const RunTracks huge = readRunTracks(write("huge.rawlog", 1.0, 1000000000000ull));
  EXPECT_TRUE(huge.status.clean);
  EXPECT_EQ(huge.pointCount, 1000000000000ull);
  ASSERT_EQ(huge.finalValues.size(), 4u);
  EXPECT_DOUBLE_EQ(huge.finalValues[3], 0.5);
}

TEST(RunTracks, AFileThatIsNotARawlogIsAnInputError) {
  const auto dir = testing::scratchDir("run_tracks_not_rawlog");
  testing::writeFile(dir / "x.rawlog", "not a rawlog");
  EXPECT_THROW(readRunTracks(dir / "x.rawlog"), InputError);
  EXPECT_THROW(readRunTracks(dir / "missing.rawlog"), InputError);
}

TEST(RunTracks, PoseAtInterpolatesPositionAndYawTheShortWay) {
  UnitTrack track;
  track.poses.push_back({0.0, world::Vec3(0, 0, 0), 3.0, 0, 0});
  track.poses.push_back({1.0, world::Vec3(2, 4, 6), -3.0, 0, 0});
  const PoseSample mid = poseAt(track, 0.5);
  EXPECT_NEAR((mid.position - world::Vec3(1, 2, 3)).norm(), 0.0, 1e-12);
  // From 3 rad to -3 rad through pi, not through 0.
  EXPECT_NEAR(std::abs(mid.yaw), M_PI, 1e-9);
  EXPECT_EQ(poseAt(track, -1.0).position, world::Vec3(0, 0, 0));
  EXPECT_EQ(poseAt(track, 5.0).position, world::Vec3(2, 4, 6));
}

}  // namespace
}  // namespace coinspect::eval
