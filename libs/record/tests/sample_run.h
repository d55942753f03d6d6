// A small deterministic recorded run, shared by the rawlog tests and the rawlog-edit end-to-end
// program: header, two units with pose + IMU at 0 and 0.05 s, one LiDAR sweep, and one object of
// each project class. Counts per label are in kSampleCounts.
#pragma once

#include <filesystem>
#include <map>
#include <string>

#include "coinspect/record/observations.h"
#include "coinspect/record/rawlog_writer.h"
#include "coinspect/sensing/capture_state.h"
#include "coinspect/sensing/inspection_scorer.h"
#include "coinspect/sensing/lidar.h"

namespace coinspect::record::sample {

inline RunHeader sampleHeader() {
  return RunHeader{"0.1.0", 42, "00ff12ab", "[mission]\nduration = 10\n"};
}

// Objects per sensor label in the sample (the header comment has no label).
inline const std::map<std::string, int> kSampleCounts = {
    {"jurong.pose", 2},  {"jurong.imu", 2},     {"raffles.pose", 2},   {"raffles.imu", 2},
    {"jurong.lidar", 1}, {"raffles.gimbal", 1}, {"raffles.camera", 1}, {"gcs.links", 1},
    {"gcs.messages", 1}, {"mission.event", 1},  {"gcs.tally", 1}};

inline void writeSampleRun(const std::filesystem::path& path, double flushPeriod = 1.0) {
  RawlogWriter writer(path, sampleHeader(), flushPeriod);
  for (double t : {0.0, 0.05}) {
    Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
    pose.translation() = Eigen::Vector3d(1.0 + t, 2.0, 3.0);
    writer.writeGroundTruth("jurong", t, pose, {1.0, 0.0, 0.0}, {0.0, 0.0, 0.5});
    pose.linear() = Eigen::AngleAxisd(0.5, Eigen::Vector3d::UnitZ()).toRotationMatrix();
    writer.writeGroundTruth("raffles", t, pose, {0.0, -1.0, 0.0}, {0.0, 0.0, 0.0});
  }
  sensing::LidarScan scan;
  scan.time = 0.05;
  scan.points = {{1.0f, 0.0f, 0.0f}, {0.0f, 2.0f, 0.0f}, {0.0f, 0.0f, 3.0f}};
  writer.writeLidar("jurong", scan);
  writer.writeGimbal("raffles", 0.05, 0.25, -0.5, 0.0, 0.125);
  sensing::CaptureState state;
  state.linearVelocity = {0.0, -1.0, 0.0};
  state.gimbalYaw = 0.25;
  state.gimbalPitch = -0.5;
  sensing::PointScore seen;
  seen.index = 4;
  seen.seen = true;
  seen.qBlur = 1.0;
  seen.qRes = 0.5;
  seen.score = 0.5;
  seen.counted = true;
  sensing::PointScore hidden;
  hidden.index = 5;
  hidden.reason = sensing::NotSeenReason::BehindCamera;
  state.position = {1.0, 2.0, 3.0};
  state.yaw = 0.5;
  writer.writeCapture("raffles", 0.05, Eigen::Isometry3d::Identity(), state,
                      {{Eigen::Vector3d(4.0, 5.0, 6.0), 0.5}}, {seen, hidden});
  writer.writeLinkChanges(0.05, {{"jurong", "raffles", true}});
  writer.writeMessages(0.05, {{"jurong", "gcs", "map", 2048, true}});
  writer.writeEvent(0.05, MissionEventKind::Start, "", "sample");
  writer.writeTally(0.05, {{4, 0.5}}, 1, 10, 0.5);
  writer.close();
}

}  // namespace coinspect::record::sample
