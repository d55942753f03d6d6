#include "mission_recorder.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>

#include "coinspect/comms/network.h"
#include "coinspect/core/error.h"
#include "coinspect/record/observations.h"
#include "coinspect/sensing/camera_model.h"
#include "coinspect/sensing/lidar.h"
#include "mission_impl.h"

namespace coinspect::sim {

namespace {

Eigen::Isometry3d bodyPose(const vehicle::VehicleState& state) {
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.linear() = (Eigen::AngleAxisd(state.yaw, Eigen::Vector3d::UnitZ()) *
                   Eigen::AngleAxisd(state.pitch, Eigen::Vector3d::UnitY()) *
                   Eigen::AngleAxisd(state.roll, Eigen::Vector3d::UnitX()))
                      .toRotationMatrix();
  pose.translation() = state.position;
  return pose;
}

// MissionEvent kinds (mission.cpp) as the rawlog's numbered kinds, which carry the same names
// (record::toString), so that events.csv, the rawlog's text and the replay read alike.
record::MissionEventKind eventKind(const std::string& kind) {
  for (int k = 0; k <= static_cast<int>(record::kLastMissionEventKind); ++k) {
    const auto candidate = static_cast<record::MissionEventKind>(k);
    if (kind == record::toString(candidate)) return candidate;
  }
  COINSPECT_ASSERT(!"a mission event kind without a rawlog kind");
  return record::MissionEventKind::Failure;
}

}  // namespace

MissionRecorder::MissionRecorder(const std::filesystem::path& path, const record::RunHeader& header,
                                 const record::RecordOptions& options,
                                 const std::vector<UnitRuntime>& units, size_t pointCount,
                                 double physicsStep)
    : path_(path),
      options_(options),
      groundTruthPeriod_(
          std::max(1LL, std::llround(1.0 / (options.groundTruthRate * physicsStep)))),
      previousLinks_(units.size()),
      previousValues_(pointCount, 0.0f) {
  for (const auto& unit : units)
    names_.push_back(unit.spec->name);
  writer_ = std::make_unique<record::RawlogWriter>(path, header, options.flushPeriod);
}

MissionRecorder::~MissionRecorder() = default;

template <class Write>
void MissionRecorder::guarded(Write&& write) {
  if (!writer_ || error_) return;
  try {
    write(*writer_);
  } catch (const InputError& e) {
    error_ = e.what();
    // Close what can be closed: the trailer will most likely fail too (disk full), but the
    // prefix up to the last flush stays readable either way.
    try {
      writer_->close();
    } catch (const InputError&) {
    }
    writer_.reset();
  }
}

void MissionRecorder::event(const MissionEvent& event) {
  guarded([&](record::RawlogWriter& w) {
    w.writeEvent(event.time, eventKind(event.kind), event.unit, event.detail);
  });
}

void MissionRecorder::groundTruth(double time, const std::vector<UnitRuntime>& units) {
  guarded([&](record::RawlogWriter& w) {
    for (const auto& unit : units) {
      const auto& state = unit.state();
      w.writeGroundTruth(unit.spec->name, time, bodyPose(state), state.velocity,
                         state.angularVelocity);
    }
  });
}

void MissionRecorder::topology(double time, const comms::LinkMatrix& links,
                               const sensing::GroundStationTally& tally, bool tallyImproved) {
  guarded([&](record::RawlogWriter& w) {
    const auto changes = links.changedSince(previousLinks_);
    if (!changes.empty()) {
      std::vector<record::LinkChangeRecord> records;
      records.reserve(changes.size());
      for (const auto& c : changes)  // a < b: lower fleet index first
        records.push_back({names_[c.a], names_[c.b], c.linked});
      w.writeLinkChanges(time, records);
      previousLinks_ = links;
    }
    if (!tallyImproved) return;
    // The merges report how many points improved, not which: compare with the last values.
    const auto& values = tally.values();
    std::vector<record::TallyChangeRecord> improved;
    for (size_t i = 0; i < values.size(); ++i) {
      if (values[i] == previousValues_[i]) continue;
      improved.push_back({static_cast<uint32_t>(i), values[i]});
      previousValues_[i] = values[i];
    }
    w.writeTally(time, improved, tally.detectedCount(), tally.size(), tally.totalScore());
  });
}

void MissionRecorder::lidar(const std::string& unit, const sensing::LidarScan& scan,
                            bool keyFrame) {
  const bool wanted = options_.lidar == record::LidarRecording::All ||
                      (options_.lidar == record::LidarRecording::KeyFrames && keyFrame);
  if (!wanted) return;
  guarded([&](record::RawlogWriter& w) { w.writeLidar(unit, scan); });
}

void MissionRecorder::capture(const std::string& unit, double time, const world::CameraSpec& camera,
                              const sensing::CaptureState& state,
                              const std::vector<sensing::SphereOccluder>& occluders,
                              const std::vector<sensing::PointScore>& scores) {
  guarded([&](record::RawlogWriter& w) {
    const sensing::CameraPose camPose = sensing::cameraPose(camera, state);
    Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
    pose.linear() = camPose.rotation;
    pose.translation() = camPose.position;
    w.writeCapture(unit, time, pose, state, occluders, scores);
  });
}

void MissionRecorder::gimbals(double time, const std::vector<UnitRuntime>& units) {
  guarded([&](record::RawlogWriter& w) {
    for (const auto& unit : units)
      if (unit.gimbal)
        w.writeGimbal(unit.spec->name, time, unit.gimbal->yaw(), unit.gimbal->pitch(),
                      unit.gimbal->yawRate(), unit.gimbal->pitchRate());
  });
}

void MissionRecorder::message(const comms::Message& message, bool delivered) {
  if (!writer_ || error_) return;
  pendingMessages_.push_back(
      {message.from, names_[message.to], message.topic, message.sizeBytes(), delivered});
}

void MissionRecorder::misaddressed(size_t from, const std::string& to, const std::string& topic,
                                   size_t payloadBytes) {
  if (!writer_ || error_) return;
  pendingMessages_.push_back({from, to, topic, comms::kMessageHeaderBytes + payloadBytes, false});
}

void MissionRecorder::flushMessages(double time) {
  if (pendingMessages_.empty()) return;
  guarded([&](record::RawlogWriter& w) {
    std::vector<record::MessageRecord> records;
    records.reserve(pendingMessages_.size());
    for (const auto& m : pendingMessages_)
      records.push_back({names_[m.from], m.to, m.topic, m.bytes, m.delivered});
    w.writeMessages(time, records);
  });
  pendingMessages_.clear();
}

void MissionRecorder::close() {
  if (!writer_) return;
  try {
    writer_->close();
  } catch (const InputError& e) {
    if (!error_) error_ = e.what();
  }
  writer_.reset();
}

bool MissionRecorder::reportFailure() {
  if (!error_ || failureReported_) return false;
  failureReported_ = true;
  return true;
}

// --- The mission's side --------------------------------------------------------------------

// Last thing of a tick: a mission that ended closes its rawlog; a recording that failed (now,
// or in the trailer just written) ends the mission cleanly with a "recording-failed" event, so
// that the outputs of the mission so far stay valid and say why it ended.
void Mission::Impl::endRecordingTick() {
  if (!recorder) return;
  if (ended) recorder->close();
  if (recorder->reportFailure()) {
    ended = true;
    event("recording-failed", "", *recorder->error());
  }
}

void Mission::startRecording(const std::filesystem::path& rawlog, const record::RunHeader& header) {
  auto& impl = *impl_;
  COINSPECT_ASSERT(impl.tick == 0 && !impl.recorder);  // before the first step, once
  impl.recorder =
      std::make_unique<MissionRecorder>(rawlog, header, impl.config.record.options, impl.units,
                                        impl.scenario.interestPoints.size(), impl.step);
  impl.network->setSendObserver(
      [recorder = impl.recorder.get()](const comms::Message& message, bool delivered) {
        recorder->message(message, delivered);
      });
}

void Mission::stopRecording() {
  auto& impl = *impl_;
  if (!impl.recorder) return;
  impl.recorder->close();
  if (impl.recorder->reportFailure()) impl.event("recording-failed", "", *impl.recorder->error());
}

const std::optional<std::string>& Mission::recordingError() const {
  static const std::optional<std::string> none;
  return impl_->recorder ? impl_->recorder->error() : none;
}

std::optional<std::filesystem::path> Mission::recordingPath() const {
  if (!impl_->recorder) return std::nullopt;
  return impl_->recorder->path();
}

}  // namespace coinspect::sim
