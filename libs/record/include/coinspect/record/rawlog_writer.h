// RawlogWriter: records one coinspect run as an observation-only MRPT rawlog (gzip stream of
// serialized observations, written as they come: constant memory). Layout: doc/recording.md.
//
// Hooking it into a mission (what the simulator does, in simulated time):
//   RawlogWriter rawlog(runFolder / "run.rawlog", header, options.flushPeriod);
//   every 1 / options.groundTruthRate s, per unit:  rawlog.writeGroundTruth(unit, t, ...)
//   each LiDAR key frame (every sweep with LidarRecording::All):  rawlog.writeLidar(unit, scan)
//   gimbal, capture, link, message, event and tally records through the typed helpers;
//   rawlog.close() at the end. Any I/O failure (unwritable folder, disk full) throws
//   coinspect::InputError naming the file at once: the caller stops the mission.
// Labels are "<unit>.<sensor>" (sensor: pose, imu, lidar, gimbal, camera) and "gcs.links",
// "gcs.messages", "gcs.tally", "mission.event" (or "<unit>.event" for unit events).
#pragma once

#include <Eigen/Geometry>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "coinspect/record/run_header.h"

namespace mrpt::obs {
class CObservation;
}
namespace coinspect::sensing {
struct LidarScan;
struct PointScore;
struct CaptureState;
struct SphereOccluder;
}  // namespace coinspect::sensing

namespace coinspect::record {

struct LinkChangeRecord;
struct MessageRecord;
struct TallyChangeRecord;
enum class MissionEventKind : uint8_t;
namespace detail {
class GzipOutput;
}

// Which LiDAR sweeps the simulator records.
enum class LidarRecording { None, KeyFrames, All };

// What the simulator records and how often (defaults from the issue; [record] in doc/config.md).
struct RecordOptions {
  double groundTruthRate = 20.0;                     // Hz, pose + IMU per unit
  LidarRecording lidar = LidarRecording::KeyFrames;  // key frames only by default
  double flushPeriod = 1.0;                          // simulated s between flushes
};

class RawlogWriter {
 public:
  // Creates (truncates) `path` and writes the header comment. flushPeriod (simulated s): the
  // writer flushes when an observation's time has passed the last flush time + flushPeriod, so
  // a killed run leaves a readable prefix up to the last flush. Throws InputError on failure.
  RawlogWriter(const std::filesystem::path& path, const RunHeader& header,
               double flushPeriod = RecordOptions{}.flushPeriod);
  ~RawlogWriter();  // closes if close() was not called; errors there are lost: call close()
  RawlogWriter(const RawlogWriter&) = delete;
  RawlogWriter& operator=(const RawlogWriter&) = delete;

  // Appends any observation (its timestamp and sensorLabel must be set by the caller).
  void write(const mrpt::obs::CObservation& observation);

  // "<unit>.pose" CObservationRobotPose (pose in the world, zero covariance) and "<unit>.imu"
  // CObservationIMU (linear velocity in the world frame, angular velocity in the body frame).
  void writeGroundTruth(const std::string& unit, double time, const Eigen::Isometry3d& bodyPose,
                        const Eigen::Vector3d& linearVelocity,
                        const Eigen::Vector3d& angularVelocity);
  // "<unit>.lidar" CObservationPointCloud (sensing::toObservation), time = scan.time.
  void writeLidar(const std::string& unit, const sensing::LidarScan& scan);
  // "<unit>.gimbal" CObservationCoinspectGimbal.
  void writeGimbal(const std::string& unit, double time, double yaw, double pitch, double yawRate,
                   double pitchRate);
  // "<unit>.camera" CObservationCoinspectCapture: cameraPose is the camera in the world; the
  // body state, velocities and gimbal state come from `state`, the other UAVs from `occluders`
  // (both exactly as the scorer received them); of `scores` (as the scorer returned them) only
  // the points the camera saw are kept: eval scores the others again if it needs them.
  void writeCapture(const std::string& unit, double time, const Eigen::Isometry3d& cameraPose,
                    const sensing::CaptureState& state,
                    const std::vector<sensing::SphereOccluder>& occluders,
                    const std::vector<sensing::PointScore>& scores);
  // "gcs.links" CObservationCoinspectLinks.
  void writeLinkChanges(double time, const std::vector<LinkChangeRecord>& changes);
  // "gcs.messages" CObservationCoinspectMessages.
  void writeMessages(double time, const std::vector<MessageRecord>& messages);
  // "<unit>.event", or "mission.event" when unit is empty: CObservationCoinspectEvent.
  void writeEvent(double time, MissionEventKind kind, const std::string& unit,
                  const std::string& detail);
  // "gcs.tally" CObservationCoinspectTally.
  void writeTally(double time, const std::vector<TallyChangeRecord>& changes, uint64_t detected,
                  uint64_t pointCount, double totalScore);

  void flush();  // flushes now (throws InputError on failure)
  void close();  // writes the gzip trailer; throws InputError on failure
  uint64_t objectCount() const { return objects_; }  // header comment included
  const std::filesystem::path& path() const { return path_; }

 private:
  void writeAt(const mrpt::obs::CObservation& observation, double time);
  [[noreturn]] void fail(const std::string& what);

  std::filesystem::path path_;
  double flushPeriod_;
  double lastFlushTime_ = 0.0;
  uint64_t objects_ = 0;
  std::unique_ptr<detail::GzipOutput> out_;
};

}  // namespace coinspect::record
