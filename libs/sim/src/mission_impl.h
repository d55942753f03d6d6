// The mission's model (constant during the run) and state (everything that changes).
#pragma once

#include <chrono>
#include <deque>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "coinspect/agent/strategy.h"
#include "coinspect/comms/key_frame_exchange.h"
#include "coinspect/comms/link_model.h"
#include "coinspect/comms/network.h"
#include "coinspect/core/hash.h"
#include "coinspect/core/worker_pool.h"
#include "coinspect/sensing/camera_model.h"
#include "coinspect/sensing/inspection_scorer.h"
#include "coinspect/sensing/score_log.h"
#include "coinspect/sim/mission.h"
#include "coinspect/vehicle/ground_vehicle.h"
#include "coinspect/vehicle/multirotor.h"
#include "coinspect/world/ray_caster.h"
#include "explorer_lidar.h"
#include "mission_features.h"
#include "mission_recorder.h"

namespace coinspect::sim {

// A decided command waiting for its tick (latency mode).
struct PendingCommand {
  long long applyTick = 0;
  agent::AgentCommand command;
};

// One unit of the fleet: its constant description and its state.
struct UnitRuntime {
  const world::UnitSpec* spec = nullptr;
  agent::Role role = agent::Role::Photographer;
  double collisionRadius = 0.0;
  std::unique_ptr<vehicle::Multirotor> vehicle;    // UAVs only (null for a ground station)
  std::unique_ptr<vehicle::GroundVehicle> ground;  // ground stations only
  std::unique_ptr<sensing::Gimbal> gimbal;         // null for a ground station
  std::unique_ptr<ExplorerLidar> lidar;            // explorers with a LiDAR
  std::unique_ptr<agent::Strategy> strategy;       // every unit
  long long decisionPeriod = 1;                    // ticks
  long long lidarPeriod = 1;                       // ticks
  long long capturePeriod = 1;                     // ticks
  long long nextCapture = 0;                       // tick
  sensing::ScoreLog log;
  double ownScore = 0.0;
  bool stationAlive = true;  // a ground station (its vehicle cannot die by itself)
  std::string deathCause;
  double distanceFlown = 0.0;  // driven, for a ground station
  world::Vec3 lastPosition = world::Vec3::Zero();
  size_t captures = 0;
  long long badFeatureIds = 0;  // assignments naming no feature (counted as rejected commands)
  // [energy]: the battery (not limited: capacity 0), its level (fraction), the lowest level it
  // reached, whether it is charging and for how long it has charged in all (s).
  agent::BatterySpec battery;
  double energy = 1.0;
  double lowestEnergy = 1.0;
  bool charging = false;
  double chargedFor = 0.0;
  // Gathered between two decisions.
  std::vector<agent::CaptureReport> pendingCaptures;
  std::vector<agent::KeyFrameView> pendingOwnKeyFrames;
  std::vector<agent::KeyFrameView> keyFrames;  // all own key frames, by id
  agent::LidarView lidarView;
  // Latency mode: decided commands not applied yet, in decision order (apply ticks ascending).
  std::deque<PendingCommand> pendingCommands;

  bool isUav() const { return vehicle != nullptr; }
  bool alive() const { return vehicle ? vehicle->alive() : stationAlive; }
  const vehicle::VehicleState& state() const {
    return vehicle ? vehicle->state() : ground->state();
  }
};

struct Mission::Impl {
  // Model.
  MissionConfig config;
  world::Scenario scenario;
  std::unique_ptr<world::RayCaster> caster;
  std::unique_ptr<comms::LinkModel> linkModel;
  std::vector<agent::BoxView> boxes;
  double budget = 0.0;
  double step = 0.0025;
  long long controlPeriod = 20;  // ticks per controller tick (digest)
  long long gimbalPeriod = 20;   // ticks, 20 Hz
  long long monitorPeriod = 4;   // ticks, collisions and the clock rule (100 Hz)
  long long topologyPeriod = 8;  // ticks, 50 Hz
  std::vector<size_t> stations;  // indices of the ground stations, in fleet order
  long long featurePeriod = 40;  // ticks, explorers' feature detector (10 Hz)

  // State.
  std::vector<UnitRuntime> units;
  std::unique_ptr<sensing::InspectionScorer> scorer;
  sensing::GroundStationTally tally;
  comms::LinkMatrix links;
  std::unique_ptr<comms::Network> network;
  std::unique_ptr<comms::KeyFrameExchange> exchange;
  std::unique_ptr<FeatureTracker> features;        // objective = features only
  bool allCollected = false;                       // the stations hold every feature
  std::vector<size_t> faultUnits;                  // per fault
  std::vector<std::vector<size_t>> blackoutUnits;  // per blackout (empty: all links)
  std::vector<size_t> faultsApplied;               // 0/1 per fault
  std::vector<uint8_t> blackoutActive;
  long long tick = 0;
  bool started = false;
  double startTime = 0.0;
  bool ended = false;
  std::vector<MissionEvent> events;
  // FNV-1a from this start value (the offset basis with its last digit missing, as since the
  // first digests): kept so that digests compare with earlier runs.
  uint64_t digest = 1469598103934665603ull;
  long long collisionDeaths = 0;
  uint64_t keyFrameCount = 0;
  uint64_t misaddressed = 0;  // messages to a unit that does not exist
  double syncedTo = 0.0;
  std::vector<sensing::PointScore> scores;  // buffer
  sensing::Occluders occluders;             // buffer

  // Threads for the units' decisions and LiDAR sweeps (Mission::setThreads); none: all on
  // the loop's thread.
  std::unique_ptr<core::WorkerPool> workers;

  std::function<void()> controlTickObserver;  // set through Mission::setControlTickObserver
  std::unique_ptr<MissionRecorder> recorder;  // set through Mission::startRecording

  // Timing (wall clock, reported only; in latency mode it also delays commands).
  StageTimes stages;
  double wallTime = 0.0;
  DecisionTimes decisionTimes;  // Strategy::decide alone
  // Realtime mode: the wall clock and simulated time of the first step, the pacing reference.
  std::optional<std::chrono::steady_clock::time_point> paceWallStart;
  double paceSimStart = 0.0;

  Impl(world::Scenario scenario, MissionConfig config, const Config& ini,
       const agent::StrategyRegistry& registry);

  double now() const { return static_cast<double>(tick) * step; }
  size_t unitIndexOf(const std::string& name, const std::string& where) const;
  void event(const std::string& kind, const std::string& unit, const std::string& detail);
  void kill(size_t unit, const std::string& cause);
  void updateFallFloor(UnitRuntime& unit);

  bool stepOnce();
  void syncVehicles();
  void advanceStation(UnitRuntime& unit, double dt);
  void applyFaultsAndBlackouts();
  void monitor();
  void updateEnergy(double dt);  // mission_energy.cpp
  void updateTopology();
  void sweepLidars();
  void capture(size_t unit);
  void decideAll();  // every live unit whose decision is due at this tick
  void applyCommand(size_t unit, const agent::AgentCommand& command);
  void applyDueCommands(size_t unit);
  bool commandDue() const;
  void paceToWallClock();
  void hashStates();
  void endRecordingTick();
  agent::AgentView observe(size_t unit);
  std::vector<bool> aliveFlags() const;
};

}  // namespace coinspect::sim
