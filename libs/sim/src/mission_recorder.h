// Records a mission as a rawlog while it runs (doc/recording.md): the loop calls one hook per
// stage of a tick, so observations land in the file in the order the loop produces them.
// Hooks never throw: the first write error is kept (error()), every later hook does nothing,
// and the mission ends at the end of that tick (Mission::Impl::endRecordingTick).
#pragma once

#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "coinspect/comms/link_matrix.h"
#include "coinspect/record/rawlog_writer.h"
#include "coinspect/sensing/inspection_scorer.h"
#include "coinspect/sensing/score_log.h"
#include "coinspect/sim/mission_summary.h"
#include "coinspect/world/fleet.h"

namespace coinspect::comms {
struct Message;
}
namespace coinspect::sensing {
struct LidarScan;
}

namespace coinspect::sim {

struct UnitRuntime;

class MissionRecorder {
 public:
  // Opens the rawlog and writes the header: throws InputError at once (before the mission
  // starts) when the file cannot be written. `units` fixes the fleet order and names.
  MissionRecorder(const std::filesystem::path& path, const record::RunHeader& header,
                  const record::RecordOptions& options, const std::vector<UnitRuntime>& units,
                  size_t pointCount, double physicsStep);
  ~MissionRecorder();
  MissionRecorder(const MissionRecorder&) = delete;
  MissionRecorder& operator=(const MissionRecorder&) = delete;

  // Ground truth is sampled every groundTruthPeriod ticks (t = 0 included).
  bool groundTruthDue(long long tick) const { return tick % groundTruthPeriod_ == 0; }

  void event(const MissionEvent& event);
  // Pose + IMU of every unit, in fleet order; the states must be synced to `time`.
  void groundTruth(double time, const std::vector<UnitRuntime>& units);
  // After a topology update: the link pairs that changed since the last update, then the
  // points whose ground-station value improved (nothing is written when nothing changed).
  // `tallyImproved`: the merges of this update improved some point (else the values are not
  // compared at all, which would cost a pass over every point at 50 Hz).
  void topology(double time, const comms::LinkMatrix& links,
                const sensing::GroundStationTally& tally, bool tallyImproved);
  void lidar(const std::string& unit, const sensing::LidarScan& scan, bool keyFrame);
  void capture(const std::string& unit, double time, const world::CameraSpec& camera,
               const sensing::CaptureState& state,
               const std::vector<sensing::SphereOccluder>& occluders,
               const std::vector<sensing::PointScore>& scores);
  // The gimbal state of every UAV after a gimbal update.
  void gimbals(double time, const std::vector<UnitRuntime>& units);
  // A message the network has just decided about (Network::SendObserver); buffered until
  // flushMessages writes the tick's messages as one `gcs.messages` record.
  void message(const comms::Message& message, bool delivered);
  // A message the mission dropped because no other unit has that name: recorded as dropped
  // with the name it was sent to, so that the records add up to the summary's counters.
  void misaddressed(size_t from, const std::string& to, const std::string& topic,
                    size_t payloadBytes);
  void flushMessages(double time);

  // Writes the gzip trailer; a failure is kept in error(). Idempotent.
  void close();
  bool closed() const { return !writer_; }
  bool failed() const { return error_.has_value(); }
  const std::optional<std::string>& error() const { return error_; }
  const std::filesystem::path& path() const { return path_; }
  // True once, the first time it is asked after a failure (the mission reports it as an event).
  bool reportFailure();

 private:
  // Runs `write` unless closed or failed; a thrown InputError becomes error() and the writer
  // is closed as far as it can be.
  template <class Write>
  void guarded(Write&& write);

  std::filesystem::path path_;
  record::RecordOptions options_;
  long long groundTruthPeriod_ = 1;
  std::vector<std::string> names_;  // fleet order
  std::unique_ptr<record::RawlogWriter> writer_;
  std::optional<std::string> error_;
  bool failureReported_ = false;
  comms::LinkMatrix previousLinks_;  // nothing linked before the first update
  std::vector<float> previousValues_;
  struct PendingMessage {
    size_t from = 0;
    std::string to;
    std::string topic;
    uint64_t bytes = 0;
    bool delivered = false;
  };
  std::vector<PendingMessage> pendingMessages_;  // of the current tick
};

}  // namespace coinspect::sim
