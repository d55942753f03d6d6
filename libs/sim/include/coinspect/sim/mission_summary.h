// What a mission reports when it ends: score, collisions, traffic, timing.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "coinspect/agent/commands.h"

namespace coinspect::sim {

// Something that happened, for the summary and (later) the recorder.
struct MissionEvent {
  double time = 0.0;  // s since the simulation began
  std::string kind;   // mission-start, mission-end, no-takeoff, collision, death, fault,
                      // blackout-start, blackout-end, charge-start, charge-end, and the
                      // feature missions' kinds (mission_recorder.cpp maps them all)
  std::string unit;   // empty for mission-wide events
  std::string detail;
};

struct UnitSummary {
  std::string name;
  std::string role;
  bool alive = true;
  std::string deathCause;      // empty while alive
  double distanceFlown = 0.0;  // m, while alive
  size_t captures = 0;
  size_t detected = 0;                 // points in the unit's own log
  double ownScore = 0.0;               // total of its own log
  std::optional<double> lowestEnergy;  // [energy]: the lowest battery level (limited UAVs only)
  double chargedFor = 0.0;             // s spent charging at stations
  long long rejectedCommands = 0;
};

// Wall-clock seconds per stage of the loop (for benchmarks; they never influence results).
struct StageTimes {
  double physics = 0.0, decisions = 0.0, lidar = 0.0, topology = 0.0, scoring = 0.0,
         collisions = 0.0;
  double pacing = 0.0;  // realtime mode: asleep, waiting for the wall clock
};

// Wall-clock time of Strategy::decide calls: in latency mode, the delays of their commands.
struct DecisionTimes {
  uint64_t count = 0;
  double total = 0.0;          // s
  double max = 0.0;            // s
  std::vector<float> samples;  // s, one per decision (the percentiles need them all)
  double mean() const { return count ? total / static_cast<double>(count) : 0.0; }
  // The q-quantile (0 <= q <= 1, nearest rank) of the compute time per decision, s; 0 if none.
  double quantile(double q) const;
};

// Feature missions (doc/features.md). Times are on the mission clock (s since take-off).
struct FeatureUnitSummary {
  // Seconds in each agent::Activity the unit reported, alive and after take-off.
  std::array<double, agent::kActivityCount> activitySeconds{};
  size_t detected = 0;   // features its own detector found
  size_t inspected = 0;  // inspections it completed
  size_t held = 0;       // inspection results it holds at the end
};

struct FeatureSummary {
  bool enabled = false;
  size_t total = 0;
  size_t discovered = 0, assigned = 0, inspected = 0, collected = 0;
  double finishRate() const {
    return total ? static_cast<double>(collected) / static_cast<double>(total) : 0.0;
  }
  std::optional<double> finishTime;  // when the station held every feature
  uint64_t meetingsGcsExplorer = 0, meetingsExplorerInspector = 0, meetingsOther = 0;
  // Explorers' promised station meetings (AgentCommand::stationMeetingTime), each counted once
  // it is settled: linked with a station within the tolerance of the promised time (on time),
  // met (linked again after a break) and replaced before that window (early), first linked
  // after the window (late), not linked by then nor before the promise ended (missed), or
  // replaced before its window without a meeting (rescheduled). doc/features.md.
  uint64_t promisesOnTime = 0, promisesEarly = 0, promisesLate = 0, promisesMissed = 0,
           promisesRescheduled = 0;
  // Per feature, when it was first discovered, assigned, inspected, collected (NaN: never).
  std::vector<double> discoveredAt, assignedAt, inspectedAt, collectedAt;
  std::vector<uint8_t> highPriority;  // per feature: 1 when high priority
  // The high-priority features: how many, collected, when the last of them was (all collected).
  size_t priorityTotal = 0, priorityCollected = 0;
  std::optional<double> priorityFinishTime;
  std::vector<FeatureUnitSummary> units;  // fleet order
};

struct MissionSummary {
  std::string scenario;
  std::string strategy;
  uint64_t seed = 0;
  std::string scoring;
  double score = 0.0;  // Q at the ground station
  size_t detected = 0;
  size_t totalPoints = 0;
  std::vector<UnitSummary> units;
  size_t collisions = 0;  // units that died in a collision
  size_t deaths = 0;
  uint64_t messagesSent = 0, messagesDelivered = 0, messagesDropped = 0;
  uint64_t keyFrames = 0, keyFramesDelivered = 0;
  long long rejectedCommands = 0;
  bool started = false;
  double startTime = 0.0;    // s of simulated time when the mission clock started
  double missionTime = 0.0;  // s on the mission clock at the end
  double budget = 0.0;
  double simTime = 0.0;   // s simulated in total
  double wallTime = 0.0;  // s
  double realTimeFactor() const { return wallTime > 0.0 ? simTime / wallTime : 0.0; }
  StageTimes stages;
  std::string runMode = "lockstep";      // lockstep, latency or realtime
  double requestedRealtimeFactor = 1.0;  // realtime: the pace asked for
  DecisionTimes decisionTimes;
  size_t threads = 1;  // threads the decisions and sweeps ran on (changes wall times, not results)
  FeatureSummary features;
};

// Human-readable summary, one topic per line ("score ...", "collisions ...", ...).
std::string formatSummary(const MissionSummary& summary);

}  // namespace coinspect::sim
