// The mission part of a run's INI file ([mission], [strategy], [fault.<n>], [blackout.<n>],
// [record]), read strictly; every key is documented in doc/config.md, "Missions (coinspect run)".
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "coinspect/core/config.h"
#include "coinspect/sensing/feature_detection.h"
#include "coinspect/sensing/inspection_scorer.h"
#include "coinspect/sim/record_config.h"
#include "coinspect/world/generators.h"
#include "coinspect/world/scenario.h"

namespace coinspect::sim {

// A unit stops working (motors off, it falls) at a given simulated time.
struct FaultSpec {
  std::string unit;
  double at = 0.0;  // s since the simulation began
};

// Links are down in [from, to): all of them, or only those of the listed units.
struct BlackoutSpec {
  double from = 0.0;
  double to = 0.0;
  std::vector<std::string> units;  // empty: every link
};

// How simulated time relates to the wall clock (doc/architecture.md, "Run modes").
enum class RunMode {
  Lockstep,  // a decision's command applies at the tick it was decided (deterministic)
  Latency,   // a command applies once the decision's measured compute time has passed
  Realtime,  // lockstep, paced so that simulated time never runs ahead of the wall clock
};
std::string toString(RunMode mode);

// What a mission is after: the CARIC score over interest points, or SLEI3D's features (the
// interest points, detected by explorers, inspected by inspectors, collected by the ground
// station through meetings; doc/features.md).
enum class Objective { Points, Features };

// [features]: only with objective = features.
struct FeatureConfig {
  sensing::FeatureSensor sensor;  // explorers' detector
  // m, per explorer in fleet order (heterogeneous ranges); empty: sensor.range for all.
  std::vector<double> explorerRanges;
  double inspectTime = 3.0;            // s of consecutive captures that count a feature
  double inspectScore = 0.2;           // CARIC score a capture needs to count a feature
  double meetingGap = 2.0;             // s a pair's link must have been down for a new meeting
  bool endWhenCollected = true;        // the mission ends when the station holds every feature
  double punctualityTolerance = 10.0;  // s either side of a promised station meeting (delta)
  // Boxes whose features are high priority (SLEI3D's urgent features): detectors report it.
  std::vector<std::string> priorityBoxes;
};

// [energy]: explorers fly on a battery that drains while airborne and charges near a ground
// station (SLEI3D's energy limits; doc/features.md, "Energy").
struct EnergyConfig {
  double capacity = 0.0;     // s of flight from full to empty
  double chargeTime = 0.0;   // s from empty to full
  double chargeRange = 3.0;  // m from a live ground station within which a UAV charges
  double startLevel = 1.0;   // fraction of the capacity at the start
};

struct MissionConfig {
  std::string source;    // the INI file, for error messages
  std::string scenario;  // generator name, scenario.ini or CARIC folder (resolved path)
  uint64_t scenarioSeed = 1;
  std::optional<world::SleiFleet> fleet;  // replaces a generated slei-* scene's fleet
  uint64_t seed = 1;
  std::optional<double> budget;  // s; the scenario's when absent
  sensing::ScoringMode scoring = sensing::ScoringMode::Caric;
  std::string links = "caric";
  double linkRange = 100.0;         // m, for links = range
  double startHeight = 0.1;         // m above the ground
  double startSpeed = 0.1;          // m/s
  double physicsStep = 0.0025;      // s
  double startTimeout = 60.0;       // s without take-off before the run gives up
  double gcsSpeed = 0.0;            // m/s, ground stations' top speed (0: static, CARIC)
  std::filesystem::path airframes;  // airframes.ini
  std::string explorerAirframe = "explorer";
  std::string photographerAirframe = "photographer";
  std::filesystem::path lidars;                 // lidars.ini
  std::string explorerLidar = "vlp16-tilting";  // "none" disables the LiDAR
  RunMode runMode = RunMode::Lockstep;
  double realtimeFactor = 1.0;  // realtime: simulated s per wall s
  Objective objective = Objective::Points;
  FeatureConfig features;              // objective = features
  std::optional<EnergyConfig> energy;  // [energy]; absent: batteries are not limited
  std::string strategy;
  std::vector<FaultSpec> faults;
  std::vector<BlackoutSpec> blackouts;
  RecordConfig record;  // [record]

  // Reads the keys above (marking them used); `seedOverride` replaces [mission] seed.
  static MissionConfig read(const Config& config, std::optional<uint64_t> seedOverride = {});
};

// The installed defaults (share/coinspect) of this build.
std::filesystem::path defaultShareDir();

// Builds the scenario named by `config.scenario`: a CARIC folder (box_description.yaml), a folder
// with scenario.ini or an .ini file, else a generator name.
world::Scenario loadMissionScenario(const MissionConfig& config);

}  // namespace coinspect::sim
