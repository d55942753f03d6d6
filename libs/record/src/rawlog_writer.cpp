#include "coinspect/record/rawlog_writer.h"

#include <mrpt/core/Clock.h>
#include <mrpt/obs/CObservationComment.h>
#include <mrpt/obs/CObservationIMU.h>
#include <mrpt/obs/CObservationPointCloud.h>
#include <mrpt/obs/CObservationRobotPose.h>
#include <mrpt/poses/CPose3D.h>
#include <mrpt/serialization/CArchive.h>

#include <cmath>

#include "coinspect/core/error.h"
#include "coinspect/record/observations.h"
#include "coinspect/sensing/capture_state.h"
#include "coinspect/sensing/inspection_scorer.h"
#include "coinspect/sensing/lidar.h"
#include "coinspect/sensing/lidar_observation.h"
#include "coinspect/sensing/sphere_occluder.h"
#include "gzip_streams.h"

namespace coinspect::record {
namespace {

// Level 1: recording must not slow the simulator down; rawlogs are recompressible offline.
constexpr int kCompressionLevel = 1;

mrpt::Clock::time_point toTimestamp(double time) {
  return mrpt::Clock::fromDouble(time);
}

PoseRecord toPoseRecord(const Eigen::Isometry3d& pose) {
  const Eigen::Quaterniond q(pose.rotation());
  const Eigen::Vector3d& p = pose.translation();
  return PoseRecord{{p.x(), p.y(), p.z()}, {q.w(), q.x(), q.y(), q.z()}};
}

std::string label(const std::string& unit, const char* sensor) {
  return unit + "." + sensor;
}

// An observation of class T with its sensor label and simulated-time stamp set.
template <class T>
T stamped(std::string sensorLabel, double time) {
  T observation;
  observation.sensorLabel = std::move(sensorLabel);
  observation.timestamp = toTimestamp(time);
  return observation;
}

}  // namespace

RawlogWriter::RawlogWriter(const std::filesystem::path& path, const RunHeader& header,
                           double flushPeriod)
    : path_(path), flushPeriod_(flushPeriod) {
  if (!(flushPeriod > 0.0) || !std::isfinite(flushPeriod))
    throw InputError(path_.string(), "flush period",
                     "must be a positive number of seconds, got " + std::to_string(flushPeriod));
  out_ = std::make_unique<detail::GzipOutput>(path_.string(), kCompressionLevel);
  if (out_->failed()) fail(out_->error());
  mrpt::obs::CObservationComment comment;
  comment.text = formatRunHeader(header);
  comment.timestamp = toTimestamp(0.0);
  writeAt(comment, 0.0);
  // The header is written through at once: even a run killed in its first second leaves a
  // valid header, and an unwritable or full disk is reported here, before a mission starts.
  if (!out_->syncFlush(true)) fail(out_->error());
}

RawlogWriter::~RawlogWriter() {
  if (out_) out_->close();
}

void RawlogWriter::fail(const std::string& what) {
  throw InputError(path_.string(), "object " + std::to_string(objects_), what);
}

void RawlogWriter::write(const mrpt::obs::CObservation& observation) {
  writeAt(observation, mrpt::Clock::toDouble(observation.timestamp));
}

void RawlogWriter::writeAt(const mrpt::obs::CObservation& observation, double time) {
  if (!out_) fail("the rawlog is already closed");
  try {
    auto archive = mrpt::serialization::archiveFrom(*out_);
    archive << observation;
  } catch (const std::exception& e) {
    fail(out_->failed() ? out_->error() : std::string(e.what()));
  }
  if (out_->failed()) fail(out_->error());
  ++objects_;
  if (time >= lastFlushTime_ + flushPeriod_) {
    flush();
    lastFlushTime_ = time;
  }
}

void RawlogWriter::writeGroundTruth(const std::string& unit, double time,
                                    const Eigen::Isometry3d& bodyPose,
                                    const Eigen::Vector3d& linearVelocity,
                                    const Eigen::Vector3d& angularVelocity) {
  auto pose = stamped<mrpt::obs::CObservationRobotPose>(label(unit, "pose"), time);
  pose.pose.mean = mrpt::poses::CPose3D::FromHomogeneousMatrix(bodyPose.matrix());
  pose.pose.cov.setZero();
  writeAt(pose, time);

  auto imu = stamped<mrpt::obs::CObservationIMU>(label(unit, "imu"), time);
  imu.set(mrpt::obs::IMU_X_VEL, linearVelocity.x());
  imu.set(mrpt::obs::IMU_Y_VEL, linearVelocity.y());
  imu.set(mrpt::obs::IMU_Z_VEL, linearVelocity.z());
  imu.set(mrpt::obs::IMU_WX, angularVelocity.x());
  imu.set(mrpt::obs::IMU_WY, angularVelocity.y());
  imu.set(mrpt::obs::IMU_WZ, angularVelocity.z());
  writeAt(imu, time);
}

void RawlogWriter::writeLidar(const std::string& unit, const sensing::LidarScan& scan) {
  const auto observation = sensing::toObservation(scan, label(unit, "lidar"));
  writeAt(*observation, scan.time);
}

void RawlogWriter::writeGimbal(const std::string& unit, double time, double yaw, double pitch,
                               double yawRate, double pitchRate) {
  auto gimbal = stamped<CObservationCoinspectGimbal>(label(unit, "gimbal"), time);
  gimbal.yaw = yaw;
  gimbal.pitch = pitch;
  gimbal.yawRate = yawRate;
  gimbal.pitchRate = pitchRate;
  writeAt(gimbal, time);
}

void RawlogWriter::writeCapture(const std::string& unit, double time,
                                const Eigen::Isometry3d& cameraPose,
                                const sensing::CaptureState& state,
                                const std::vector<sensing::SphereOccluder>& occluders,
                                const std::vector<sensing::PointScore>& scores) {
  auto capture = stamped<CObservationCoinspectCapture>(label(unit, "camera"), time);
  capture.cameraPose = toPoseRecord(cameraPose);
  capture.linearVelocity = {state.linearVelocity.x(), state.linearVelocity.y(),
                            state.linearVelocity.z()};
  capture.angularVelocity = {state.angularVelocity.x(), state.angularVelocity.y(),
                             state.angularVelocity.z()};
  capture.gimbalYaw = state.gimbalYaw;
  capture.gimbalPitch = state.gimbalPitch;
  capture.gimbalYawRate = state.gimbalYawRate;
  capture.gimbalPitchRate = state.gimbalPitchRate;
  for (const auto& s : scores)
    if (s.seen)
      capture.points.push_back(ScoredPointRecord{s.index, s.seen, static_cast<uint8_t>(s.reason),
                                                 s.qBlur, s.qRes, s.score, s.counted});
  capture.bodyPosition = {state.position.x(), state.position.y(), state.position.z()};
  capture.bodyYaw = state.yaw;
  capture.bodyPitch = state.pitch;
  capture.bodyRoll = state.roll;
  capture.occluders.reserve(occluders.size());
  for (const auto& o : occluders)
    capture.occluders.push_back({{o.center.x(), o.center.y(), o.center.z()}, o.radius});
  writeAt(capture, time);
}

void RawlogWriter::writeLinkChanges(double time, const std::vector<LinkChangeRecord>& changes) {
  auto links = stamped<CObservationCoinspectLinks>("gcs.links", time);
  links.changes = changes;
  writeAt(links, time);
}

void RawlogWriter::writeMessages(double time, const std::vector<MessageRecord>& messages) {
  auto log = stamped<CObservationCoinspectMessages>("gcs.messages", time);
  log.messages = messages;
  writeAt(log, time);
}

void RawlogWriter::writeEvent(double time, MissionEventKind kind, const std::string& unit,
                              const std::string& detail) {
  auto event = stamped<CObservationCoinspectEvent>(
      unit.empty() ? "mission.event" : label(unit, "event"), time);
  event.kind = kind;
  event.unit = unit;
  event.detail = detail;
  writeAt(event, time);
}

void RawlogWriter::writeTally(double time, const std::vector<TallyChangeRecord>& changes,
                              uint64_t detected, uint64_t pointCount, double totalScore) {
  auto tally = stamped<CObservationCoinspectTally>("gcs.tally", time);
  tally.changes = changes;
  tally.detected = detected;
  tally.pointCount = pointCount;
  tally.totalScore = totalScore;
  writeAt(tally, time);
}

void RawlogWriter::flush() {
  if (!out_) fail("the rawlog is already closed");
  if (!out_->syncFlush()) fail(out_->error());
}

void RawlogWriter::close() {
  if (!out_) return;
  const bool ok = out_->close();
  const std::string error = out_->error();
  out_.reset();
  if (!ok) fail(error);
}

}  // namespace coinspect::record
