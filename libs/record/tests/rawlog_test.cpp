// Rawlog writing and reading: round trip in order, identical bytes for identical inputs,
// truncated and corrupted files read up to the damage, SIGKILL recovery, I/O errors at once.
#include <gtest/gtest.h>

#include <mrpt/core/Clock.h>
#include <mrpt/io/CMemoryStream.h>
#include <mrpt/maps/CSimplePointsMap.h>
#include <mrpt/obs/CObservationIMU.h>
#include <mrpt/obs/CObservationPointCloud.h>
#include <mrpt/obs/CObservationRobotPose.h>
#include <mrpt/serialization/CArchive.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>
#include <zlib.h>
#include <limits>

#include <vector>

#include "coinspect/core/error.h"
#include "coinspect/core/text.h"
#include "coinspect/record/rawlog_reader.h"
#include "coinspect/testing/files.h"
#include "coinspect/testing/input_errors.h"
#include "coinspect/testing/paths.h"
#include "sample_run.h"

namespace coinspect::record {
namespace {

using Observation = std::shared_ptr<mrpt::obs::CObservation>;

struct ReadResult {
  std::vector<Observation> objects;  // after the header
  ReadStatus status;
};

ReadResult readAll(const std::filesystem::path& path,
                   double latestTime = std::numeric_limits<double>::infinity()) {
  RawlogReader reader(path);
  reader.setLatestTime(latestTime);
  ReadResult result;
  Observation o;
  while (reader.next(o))
    result.objects.push_back(o);
  result.status = reader.status();
  return result;
}

template <typename T>
std::shared_ptr<T> as(const Observation& o) {
  auto typed = std::dynamic_pointer_cast<T>(o);
  EXPECT_TRUE(typed) << (o ? o->GetRuntimeClass()->className : "null");
  return typed;
}

// The whole decompressed content of a gzip file (what the reader's offsets count).
std::string gunzip(const std::filesystem::path& path) {
  gzFile f = gzopen(path.string().c_str(), "rb");
  std::string data;
  char buffer[4096];
  int n = 0;
  while ((n = gzread(f, buffer, sizeof buffer)) > 0)
    data.append(buffer, static_cast<size_t>(n));
  gzclose(f);
  return data;
}

TEST(Rawlog, SampleReadsBackInOrderWithEveryField) {
  const auto dir = testing::scratchDir("rawlog_roundtrip");
  sample::writeSampleRun(dir / "run.rawlog");
  RawlogReader reader(dir / "run.rawlog");
  EXPECT_EQ(reader.header(), sample::sampleHeader());
  const auto result = readAll(dir / "run.rawlog");
  EXPECT_TRUE(result.status.clean) << result.status.message;
  ASSERT_EQ(result.objects.size(), 15u);
  EXPECT_EQ(result.status.objects, 16u);  // + header

  const std::vector<std::string> labels = {
      "jurong.pose",    "jurong.imu",   "raffles.pose", "raffles.imu",   "jurong.pose",
      "jurong.imu",     "raffles.pose", "raffles.imu",  "jurong.lidar",  "raffles.gimbal",
      "raffles.camera", "gcs.links",    "gcs.messages", "mission.event", "gcs.tally"};
  for (size_t i = 0; i < labels.size(); ++i)
    EXPECT_EQ(result.objects[i]->sensorLabel, labels[i]) << i;
  EXPECT_EQ(mrpt::Clock::toDouble(result.objects[0]->timestamp), 0.0);
  EXPECT_EQ(mrpt::Clock::toDouble(result.objects[14]->timestamp), 0.05);

  // raffles at t = 0.05: (1.05, 2, 3), yawed 0.5 rad about z.
  const auto pose = as<mrpt::obs::CObservationRobotPose>(result.objects[6]);
  ASSERT_TRUE(pose);
  EXPECT_NEAR(pose->pose.mean.x(), 1.05, 1e-12);
  EXPECT_NEAR(pose->pose.mean.y(), 2.0, 1e-12);
  EXPECT_NEAR(pose->pose.mean.z(), 3.0, 1e-12);
  EXPECT_NEAR(pose->pose.mean.yaw(), 0.5, 1e-12);
  const auto imu = as<mrpt::obs::CObservationIMU>(result.objects[1]);
  ASSERT_TRUE(imu);
  EXPECT_EQ(imu->get(mrpt::obs::IMU_X_VEL), 1.0);
  EXPECT_EQ(imu->get(mrpt::obs::IMU_WZ), 0.5);
  const auto cloud = as<mrpt::obs::CObservationPointCloud>(result.objects[8]);
  ASSERT_TRUE(cloud && cloud->pointcloud);
  ASSERT_EQ(cloud->pointcloud->size(), 3u);
  float x = 0, y = 0, z = 0;
  cloud->pointcloud->getPoint(1, x, y, z);
  EXPECT_EQ(x, 0.0f);
  EXPECT_EQ(y, 2.0f);
  EXPECT_EQ(z, 0.0f);
  const auto gimbal = as<CObservationCoinspectGimbal>(result.objects[9]);
  ASSERT_TRUE(gimbal);
  EXPECT_EQ(gimbal->yaw, 0.25);
  EXPECT_EQ(gimbal->pitch, -0.5);
  EXPECT_EQ(gimbal->pitchRate, 0.125);
  const auto capture = as<CObservationCoinspectCapture>(result.objects[10]);
  ASSERT_TRUE(capture);
  EXPECT_EQ(capture->cameraPose, PoseRecord{});
  EXPECT_EQ(capture->linearVelocity, (std::array<double, 3>{0.0, -1.0, 0.0}));
  EXPECT_EQ(capture->gimbalYaw, 0.25);
  // Only the points the camera saw are kept.
  const std::vector<ScoredPointRecord> points = {{4, true, 0, 1.0, 0.5, 0.5, true}};
  EXPECT_EQ(capture->points, points);
  EXPECT_EQ(capture->bodyPosition, (std::array<double, 3>{1.0, 2.0, 3.0}));
  EXPECT_EQ(capture->bodyYaw, 0.5);
  EXPECT_EQ(capture->occluders, (std::vector<OccluderRecord>{{{4.0, 5.0, 6.0}, 0.5}}));
  const auto links = as<CObservationCoinspectLinks>(result.objects[11]);
  ASSERT_TRUE(links);
  EXPECT_EQ(links->changes, (std::vector<LinkChangeRecord>{{"jurong", "raffles", true}}));
  const auto messages = as<CObservationCoinspectMessages>(result.objects[12]);
  ASSERT_TRUE(messages);
  EXPECT_EQ(messages->messages, (std::vector<MessageRecord>{{"jurong", "gcs", "map", 2048, true}}));
  const auto event = as<CObservationCoinspectEvent>(result.objects[13]);
  ASSERT_TRUE(event);
  EXPECT_EQ(event->kind, MissionEventKind::Start);
  EXPECT_EQ(event->detail, "sample");
  const auto tally = as<CObservationCoinspectTally>(result.objects[14]);
  ASSERT_TRUE(tally);
  EXPECT_EQ(tally->changes, (std::vector<TallyChangeRecord>{{4, 0.5}}));
  EXPECT_EQ(tally->detected, 1u);
  EXPECT_EQ(tally->pointCount, 10u);
  EXPECT_EQ(tally->totalScore, 0.5);
}

// Feature missions record each unit's activity as events: through the writer and the reader
// they keep their kind, their unit (and its "<unit>.event" label), their activity and time.
TEST(Rawlog, ActivityChangesRoundTripAsUnitEvents) {
  const auto dir = testing::scratchDir("rawlog_activity");
  {
    RawlogWriter writer(dir / "run.rawlog", sample::sampleHeader(), 1.0);
    writer.writeEvent(2.5, MissionEventKind::ActivityChanged, "jurong", "exploring");
    writer.writeEvent(7.25, MissionEventKind::ActivityChanged, "jurong", "travelling-to-meeting");
    writer.writeEvent(7.25, MissionEventKind::Meeting, "gcs", "jurong");
    writer.close();
  }
  const auto result = readAll(dir / "run.rawlog");
  EXPECT_TRUE(result.status.clean) << result.status.message;
  ASSERT_EQ(result.objects.size(), 3u);
  const std::vector<std::pair<double, std::string>> expected = {{2.5, "exploring"},
                                                                {7.25, "travelling-to-meeting"}};
  for (size_t i = 0; i < expected.size(); ++i) {
    const auto event = as<CObservationCoinspectEvent>(result.objects[i]);
    ASSERT_TRUE(event);
    EXPECT_EQ(event->kind, MissionEventKind::ActivityChanged);
    EXPECT_EQ(event->sensorLabel, "jurong.event");
    EXPECT_EQ(event->unit, "jurong");
    EXPECT_EQ(event->detail, expected[i].second);
    EXPECT_EQ(mrpt::Clock::toDouble(event->timestamp), expected[i].first);
  }
  const auto meeting = as<CObservationCoinspectEvent>(result.objects[2]);
  ASSERT_TRUE(meeting);
  EXPECT_EQ(meeting->kind, MissionEventKind::Meeting);
}

TEST(Rawlog, SameInputsGiveIdenticalBytes) {
  const auto dir = testing::scratchDir("rawlog_determinism");
  sample::writeSampleRun(dir / "a.rawlog");
  sample::writeSampleRun(dir / "b.rawlog");
  const std::string a = testing::readFile(dir / "a.rawlog");
  ASSERT_GT(a.size(), 18u);
  EXPECT_EQ(a, testing::readFile(dir / "b.rawlog"));
  // gzip header: magic, deflate, no flags, mtime 0 (nothing from the clock).
  EXPECT_EQ(static_cast<unsigned char>(a[0]), 0x1f);
  EXPECT_EQ(static_cast<unsigned char>(a[1]), 0x8b);
  EXPECT_EQ(a.substr(4, 4), std::string(4, '\0'));
}

TEST(Rawlog, TruncatedCopiesReadTheirPrefixAndSayWhere) {
  const auto dir = testing::scratchDir("rawlog_truncated");
  sample::writeSampleRun(dir / "run.rawlog");
  const std::string bytes = testing::readFile(dir / "run.rawlog");
  const auto full = readAll(dir / "run.rawlog");
  const std::string decompressed = gunzip(dir / "run.rawlog");
  // The header is flushed on its own before anything else: cuts after that point keep it.
  const size_t headerEnd = bytes.size() / 3;
  size_t previousCount = 0;
  for (size_t cut :
       {headerEnd, bytes.size() / 2, bytes.size() * 3 / 4, bytes.size() - 9, bytes.size() - 1}) {
    SCOPED_TRACE("cut at " + std::to_string(cut) + " of " + std::to_string(bytes.size()));
    testing::writeFile(dir / "cut.rawlog", bytes.substr(0, cut));
    const auto part = readAll(dir / "cut.rawlog");
    EXPECT_FALSE(part.status.clean);
    EXPECT_GE(part.objects.size(), previousCount);
    previousCount = part.objects.size();
    ASSERT_LE(part.objects.size(), full.objects.size());
    for (size_t i = 0; i < part.objects.size(); ++i)
      EXPECT_EQ(part.objects[i]->sensorLabel, full.objects[i]->sensorLabel);
    EXPECT_EQ(part.status.objects, part.objects.size() + 1);
    EXPECT_MENTIONS(part.status.message, std::to_string(part.status.objects) +
                                             " objects read, damage at byte offset " +
                                             std::to_string(part.status.offset));
    // The offset is where the first unread object starts in the decompressed stream.
    if (part.objects.size() == full.objects.size()) {
      EXPECT_EQ(part.status.offset, decompressed.size());
      continue;
    }
    ASSERT_LT(part.status.offset, decompressed.size());
    mrpt::io::CMemoryStream rest;
    rest.assignMemoryNotOwn(decompressed.data() + part.status.offset,
                            decompressed.size() - part.status.offset);
    auto archive = mrpt::serialization::archiveFrom(rest);
    const auto next = std::dynamic_pointer_cast<mrpt::obs::CObservation>(archive.ReadObject());
    ASSERT_TRUE(next);
    EXPECT_EQ(next->sensorLabel, full.objects[part.objects.size()]->sensorLabel);
  }
  // Cutting the last bytes (gzip trailer) keeps every object but is still reported.
  EXPECT_EQ(previousCount, full.objects.size());
}

TEST(Rawlog, CorruptedFileStopsWithAMessageInsteadOfCrashing) {
  const auto dir = testing::scratchDir("rawlog_corrupted");
  sample::writeSampleRun(dir / "run.rawlog");
  std::string bytes = testing::readFile(dir / "run.rawlog");
  const size_t middle = bytes.size() / 2;
  for (size_t i = middle; i < middle + 16; ++i)
    bytes[i] = static_cast<char>(0xff);
  testing::writeFile(dir / "bad.rawlog", bytes);
  const auto part = readAll(dir / "bad.rawlog");
  EXPECT_FALSE(part.status.clean);
  EXPECT_LT(part.objects.size(), 15u);
  EXPECT_MENTIONS(part.status.message, "objects read, damage at byte offset");
}

// A timestamp damaged into another readable value (fuzzing: one 0xFF.. time made `coinspect
// replay` write frames until the disk was full, and eval called the file clean) is damage at that
// object: out of order, or past the run's latest time.
TEST(Rawlog, ImpossibleTimestampsAreDamageAtTheirObject) {
  const auto dir = testing::scratchDir("rawlog_timestamps");
  const auto write = [&](const std::string& name, std::vector<double> times) {
    RawlogWriter writer(dir / name, sample::sampleHeader(), 1.0);
    for (const double t : times)
      writer.writeEvent(t, MissionEventKind::Meeting, "jurong", "raffles");
    writer.close();
    return dir / name;
  };
  const auto inOrder = readAll(write("order.rawlog", {0.5, 1.0, 1.0, 2.0}), 3.0);
  EXPECT_TRUE(inOrder.status.clean) << inOrder.status.message;
  EXPECT_EQ(inOrder.objects.size(), 4u);

  const auto backwards = readAll(write("back.rawlog", {0.5, 1.0, 0.75, 2.0}));
  EXPECT_FALSE(backwards.status.clean);
  EXPECT_EQ(backwards.objects.size(), 2u);
  EXPECT_MENTIONS(backwards.status.message, "3 objects read, damage at byte offset");
  EXPECT_MENTIONS(
      backwards.status.message,
      "jurong.event: timestamp 0.750000 s comes before the previous object's 1.000000 s");

  const auto late = readAll(write("late.rawlog", {0.5, 1.0, 1e6}), 3.0);
  EXPECT_FALSE(late.status.clean);
  EXPECT_EQ(late.objects.size(), 2u);
  EXPECT_MENTIONS(late.status.message, "after the latest time the run can reach, 3.000000 s");
  EXPECT_TRUE(readAll(dir / "late.rawlog").status.clean);  // no bound set: in order is enough
}

// A damaged class name reaches MRPT's exception message byte for byte. The status message must
// still be valid UTF-8 (eval writes it into eval.json, which refused it and was left empty,
// found by fuzzing `coinspect eval`) and show the byte.
TEST(Rawlog, DamagedClassNameIsReportedAsPrintableText) {
  const auto dir = testing::scratchDir("rawlog_class_name");
  sample::writeSampleRun(dir / "run.rawlog");
  std::string data = gunzip(dir / "run.rawlog");
  const size_t name = data.find("CObservationIMU");
  ASSERT_NE(name, std::string::npos);
  data[name] = static_cast<char>(0x90);
  gzFile f = gzopen((dir / "bad.rawlog").string().c_str(), "wb");
  ASSERT_TRUE(f);
  ASSERT_EQ(gzwrite(f, data.data(), static_cast<unsigned>(data.size())),
            static_cast<int>(data.size()));
  gzclose(f);
  const auto part = readAll(dir / "bad.rawlog");
  EXPECT_FALSE(part.status.clean);
  EXPECT_MENTIONS(part.status.message, "\\x90Observation");
  EXPECT_EQ(printableText(part.status.message), part.status.message);
}

TEST(Rawlog, KilledWriterLeavesAReadablePrefixUpToTheLastFlush) {
  const auto dir = testing::scratchDir("rawlog_killed");
  const auto path = dir / "run.rawlog";
  int ready[2];
  ASSERT_EQ(pipe(ready), 0);
  const pid_t child = fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    // Events every 0.1 s, flush period 0.5 s: flushes after the events at 0.5, 1.0, 1.5, 2.0.
    RawlogWriter writer(path, sample::sampleHeader(), 0.5);
    for (int i = 0; i <= 24; ++i)
      writer.writeEvent(0.1 * i, MissionEventKind::Start, "u", std::to_string(i));
    const char byte = 1;
    if (write(ready[1], &byte, 1) != 1) _exit(3);
    for (;;)
      pause();  // the parent kills us here
  }
  close(ready[1]);
  char byte = 0;
  ASSERT_EQ(read(ready[0], &byte, 1), 1);
  close(ready[0]);
  kill(child, SIGKILL);
  int status = 0;
  waitpid(child, &status, 0);
  ASSERT_TRUE(WIFSIGNALED(status));

  const auto part = readAll(path);
  EXPECT_FALSE(part.status.clean);  // no gzip trailer
  // Flushes are pipelined (one may still be in the background writer when the process dies):
  // at least everything up to the flush before the last, at 1.5 s (events 0-15), reads back.
  ASSERT_GE(part.objects.size(), 16u) << part.status.message;
  for (size_t i = 0; i < part.objects.size(); ++i)
    EXPECT_EQ(as<CObservationCoinspectEvent>(part.objects[i])->detail, std::to_string(i));
}

TEST(Rawlog, UnwritableFolderFailsAtOnce) {
  const auto dir = testing::scratchDir("rawlog_unwritable");
  testing::writeFile(dir / "not-a-folder", "x");
  const auto path = dir / "not-a-folder" / "run.rawlog";
  const std::string message =
      testing::messageOf([&] { RawlogWriter writer(path, sample::sampleHeader()); });
  EXPECT_MENTIONS(message, path.string());
  EXPECT_MENTIONS(message, "cannot create");
}

TEST(Rawlog, FullDiskFailsAtOnce) {
  if (!std::filesystem::exists("/dev/full")) GTEST_SKIP() << "no /dev/full on this system";
  // The header is flushed in the constructor: the first write to a full disk fails there.
  const std::string message =
      testing::messageOf([&] { RawlogWriter writer("/dev/full", sample::sampleHeader()); });
  EXPECT_MENTIONS(message, "/dev/full");
  EXPECT_MENTIONS(message, "No space left");
}

TEST(Rawlog, NotACoinspectRawlogIsRejected) {
  const auto dir = testing::scratchDir("rawlog_foreign");
  testing::writeFile(dir / "empty.rawlog", "");
  EXPECT_MENTIONS(testing::messageOf([&] { RawlogReader reader(dir / "empty.rawlog"); }), "empty");
  EXPECT_MENTIONS(testing::messageOf([&] { RawlogReader reader(dir / "missing.rawlog"); }),
                  "cannot open");
}

TEST(RunHeader, FormatAndParseAreInverse) {
  const RunHeader header{"1.2.3", 18446744073709551615ull, "abc", "[a]\nb = 1\n\n"};
  EXPECT_EQ(parseRunHeader(formatRunHeader(header), "x"), header);
  EXPECT_MENTIONS(testing::messageOf([] { parseRunHeader("hello", "src"); }), "src");
}

}  // namespace
}  // namespace coinspect::record
