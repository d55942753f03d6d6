// A mission: the scenario, the fleet's vehicles, gimbals, LiDARs and strategies, the links and
// the ground station's tally, advanced by the deterministic multi-rate loop described in
// doc/architecture.md ("The tick").
#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "coinspect/agent/strategy.h"
#include "coinspect/core/config.h"
#include "coinspect/record/run_header.h"
#include "coinspect/sim/mission_config.h"
#include "coinspect/sim/mission_summary.h"
#include "coinspect/vehicle/vehicle_state.h"
#include "coinspect/world/scenario.h"

namespace coinspect::sim {

class Mission {
 public:
  // Reads [mission], [strategy], faults and blackouts from `ini`, builds the scenario it names
  // and one strategy per UAV from `registry` (each reads its own keys from `ini`). The caller
  // then checks ini.requireAllKeysUsed(). Throws InputError for bad input.
  Mission(const Config& ini, const agent::StrategyRegistry& registry,
          std::optional<uint64_t> seedOverride = {});
  // The same with a scenario built by the caller ([mission] scenario is then not read).
  Mission(world::Scenario scenario, const Config& ini, const agent::StrategyRegistry& registry,
          std::optional<uint64_t> seedOverride = {});
  ~Mission();
  Mission(const Mission&) = delete;
  Mission& operator=(const Mission&) = delete;

  // Runs until the mission ends (budget used up, or no take-off within start_timeout).
  void run();
  // One tick of physics_step; false once the mission has ended.
  bool step();
  // Runs until simulated time `time` or the end, whichever comes first.
  void runUntil(double time);
  bool finished() const;

  double time() const;  // simulated s
  const world::Scenario& scenario() const;
  const MissionConfig& config() const;
  const std::vector<MissionEvent>& events() const;
  MissionSummary summary() const;
  // FNV-1a over every vehicle state and gimbal angle at every controller tick (0.05 s): equal
  // digests mean equal trajectories, bit for bit.
  uint64_t stateDigest() const;

  // How many threads run the units' decisions and the LiDAR sweeps of a tick (0: one per
  // hardware thread; the default is 1, all on the caller's thread). Results do not depend on it,
  // bit for bit: a unit still sees the commands of the units before it in the fleet at the same
  // tick (they can only reach it as messages over a link, so it waits only for the units it is
  // linked with), and commands are applied in fleet order. Strategies of different units decide
  // at once, so one must not share mutable state with another unit's. Call it before the first
  // step.
  void setThreads(size_t threads);
  size_t threads() const;

  // Per-unit access for tests and tools (index in the fleet; throws InputError for a bad name).
  size_t unitIndex(const std::string& name) const;
  vehicle::VehicleState unitState(size_t unit) const;
  bool unitAlive(size_t unit) const;
  double unitOwnScore(size_t unit) const;
  double gcsScore() const;
  // The ground station's value per interest point (index order), for the score file.
  const std::vector<float>& gcsValues() const;

  // Called at every controller tick (every 0.05 s of simulated time, t = 0 included) after the
  // vehicle states are brought up to that time and before any unit decides: the place to
  // record poses. It must not change the mission; an empty function removes it.
  using ControlTickObserver = std::function<void(const Mission&)>;
  void setControlTickObserver(ControlTickObserver observer);

  // Records the run as a rawlog at `rawlog` (doc/recording.md) with the options of
  // config().record; call it once, before the first step. The file is created and the header
  // written at once: an unwritable path throws InputError here. A write error later stops the
  // mission cleanly at the end of that tick (event "recording-failed"); recordingError() then
  // holds the message, which names the file. The rawlog is closed when the mission ends.
  void startRecording(const std::filesystem::path& rawlog, const record::RunHeader& header);
  // Closes the rawlog now (for callers that stop before the end); a failure is reported as above.
  void stopRecording();
  const std::optional<std::string>& recordingError() const;
  std::optional<std::filesystem::path> recordingPath() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace coinspect::sim
