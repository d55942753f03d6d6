// report.json: what a run was (config, seed) and what it gave (score, per-unit figures,
// collisions, traffic), plus wall-clock timings kept apart under "timing" so that comparing
// two reports of the same run can skip them.
#pragma once

#include <cstdint>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace coinspect::record {

struct RunReportUnit {
  std::string name;
  std::string role;
  bool alive = true;
  std::string deathCause;      // empty while alive
  double distanceFlown = 0.0;  // m
  uint64_t captures = 0;
  uint64_t detected = 0;  // points in its own log
  double ownScore = 0.0;
  int64_t rejectedCommands = 0;
  std::optional<double> lowestEnergy;  // [energy]: lowest battery level; absent: not limited
  double chargedFor = 0.0;             // s spent charging at stations
};

struct RunReportTiming {
  double wallTime = 0.0;  // s
  double realTimeFactor = 0.0;
  std::map<std::string, double> stages;  // s per stage of the loop
  size_t threads = 1;                    // threads the decisions and LiDAR sweeps ran on
  // Wall time of the strategies' decide() calls (in latency mode, the commands' delays).
  uint64_t decisions = 0;
  double decisionTimeMean = 0.0;  // s
  double decisionTimeMax = 0.0;   // s
  double decisionTimeP50 = 0.0;   // s
  double decisionTimeP95 = 0.0;   // s
};

// Feature missions (doc/features.md); times on the mission clock, s.
struct RunReportFeatureUnit {
  std::string name;
  std::map<std::string, double> activitySeconds;  // activity name -> s
  double idleSeconds = 0.0;  // travelling to meetings + waiting (SLEI3D's idle time)
  uint64_t detected = 0, inspected = 0, held = 0;
};

struct RunReportFeatures {
  uint64_t total = 0, discovered = 0, assigned = 0, inspected = 0, collected = 0;
  double finishRate = 0.0;
  std::optional<double> finishTime;             // all collected; absent: not within the budget
  std::map<std::string, uint64_t> meetings;     // gcs_explorer, explorer_inspector, other
  std::map<std::string, uint64_t> punctuality;  // on_time, early, late, missed, rescheduled
  // discovered/assigned/inspected/collected -> the times it happened, ascending (the curves of
  // features over time: the k-th time is when the count reached k).
  std::map<std::string, std::vector<double>> timeline;
  // High-priority features ([features] priority_boxes; 0 when none): how many, collected, and
  // when all were (absent: not within the budget). Their collection times: timeline "priority".
  uint64_t priorityTotal = 0, priorityCollected = 0;
  std::optional<double> priorityFinishTime;
  std::vector<RunReportFeatureUnit> units;  // fleet order
};

struct RunReport {
  // The resolved configuration (overrides applied), section -> key -> value, as written.
  std::string configFile;
  std::map<std::string, std::map<std::string, std::string>> config;
  std::string scenario;
  std::string strategy;
  uint64_t seed = 0;
  std::string scoring;
  double score = 0.0;  // Q at the ground station
  uint64_t detected = 0;
  uint64_t totalPoints = 0;
  std::vector<RunReportUnit> units;
  uint64_t collisions = 0;
  uint64_t deaths = 0;
  uint64_t messagesSent = 0, messagesDelivered = 0, messagesDropped = 0;
  uint64_t keyFrames = 0, keyFramesDelivered = 0;
  bool started = false;
  double startTime = 0.0;    // s of simulated time when the mission clock started
  double missionTime = 0.0;  // s on the mission clock at the end
  double budget = 0.0;       // s
  double simTime = 0.0;      // s simulated in total
  // lockstep, latency (not deterministic) or realtime; the pace asked for in realtime mode.
  std::string runMode = "lockstep";
  double realtimeFactor = 1.0;
  std::optional<RunReportFeatures> features;  // objective = features only
  RunReportTiming timing;                     // wall clock: differs between equal runs
};

// The report as JSON text: keys sorted at every level, two-space indent, numbers printed
// shortest-exact, so equal reports give equal text.
std::string runReportJson(const RunReport& report);
// Writes runReportJson(report) to `path`; throws InputError if it cannot be written.
void writeRunReportJson(const std::filesystem::path& path, const RunReport& report);

}  // namespace coinspect::record
