// What the pictures of a recorded run need, read from its rawlog in one pass: each unit's pose
// samples, the ground station's tally over time and its final per-point values, and the mission
// events. Memory grows with these tracks only (every other object is read and dropped).
#pragma once

#include <cstdint>
#include <filesystem>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "coinspect/record/rawlog_reader.h"
#include "coinspect/record/run_header.h"
#include "coinspect/world/mesh.h"

namespace coinspect::record {
enum class MissionEventKind : uint8_t;
}

namespace coinspect::eval {

// One `<unit>.pose` record: simulated time (s), body position (m), Z-Y-X Euler angles (rad).
struct PoseSample {
  double time = 0.0;
  world::Vec3 position = world::Vec3::Zero();
  double yaw = 0.0, pitch = 0.0, roll = 0.0;
};

struct UnitTrack {
  std::string name;
  std::vector<PoseSample> poses;  // in time order
  // The first collision, failure or death event of the unit: when and why it stopped flying.
  std::optional<double> deathTime;
  std::string deathCause;  // the event's kind ("collision", ...), then its detail if any
};

// One `gcs.tally` record: the ground station's totals after an update.
struct TallySample {
  double time = 0.0;
  double totalScore = 0.0;  // Q
  uint64_t detected = 0;
};

// One improved point of a `gcs.tally` record.
struct TallyChange {
  double time = 0.0;
  uint32_t index = 0;
  double value = 0.0;
};

// A `mission.event` or `<unit>.event` record.
struct RunEvent {
  double time = 0.0;
  record::MissionEventKind kind{};
  std::string unit;  // empty for mission-wide events
  std::string detail;
};

struct RunTracks {
  record::RunHeader header;
  std::vector<UnitTrack> units;  // in the order of their first pose record
  std::vector<TallySample> tally;
  std::vector<TallyChange> tallyChanges;  // every improvement, in time order (for replays)
  uint64_t pointCount = 0;                // as the tally records say (0 without any)
  // Per point index, the last value the GCS held, up to the highest index any tally changed
  // (the points after it held 0).
  std::vector<double> finalValues;
  std::vector<RunEvent> events;
  double endTime = 0.0;       // latest timestamp of any object read (s)
  uint64_t objects = 0;       // objects read, header comment included
  record::ReadStatus status;  // clean, or where the rawlog is damaged and why

  // Index of the unit called `name` in `units`, or -1.
  int unitIndex(const std::string& name) const;
  // Final Q and detected count (0 when the run has no tally record).
  double finalScore() const { return tally.empty() ? 0.0 : tally.back().totalScore; }
  uint64_t finalDetected() const { return tally.empty() ? 0 : tally.back().detected; }
};

// Reads `rawlog` up to its end or its damage (then status.clean is false and status.message says
// where; the tracks hold everything before it; an object later than `latestTime` (s) is damage,
// record::RawlogReader::setLatestTime). Throws InputError when the file cannot be opened or has
// no coinspect run header, when a tally names a point beyond its point count, or when a pose is
// not finite.
RunTracks readRunTracks(const std::filesystem::path& rawlog,
                        double latestTime = std::numeric_limits<double>::infinity());

// The pose of `track` at time t: linear between samples (yaw the short way round), the first
// sample before it, the last after it. The track must not be empty.
PoseSample poseAt(const UnitTrack& track, double t);

// "mission-start", "mission-end", "collision", ... (record::toString: events.csv's names).
std::string eventKindName(record::MissionEventKind kind);
// True for the events after which a unit no longer flies (collision, fault, death).
bool isDeathEvent(record::MissionEventKind kind);

}  // namespace coinspect::eval
