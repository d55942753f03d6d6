// What `eval`, `render` and `replay` need before they read a rawlog's observations: its run
// header, the mission config it was recorded with, and the scenario it was flown in.
#pragma once

#include <filesystem>
#include <string>

#include "coinspect/core/config.h"
#include "coinspect/record/run_header.h"
#include "coinspect/sim/mission_config.h"
#include "coinspect/world/scenario.h"

namespace coinspect::app {

struct RecordedRun {
  std::filesystem::path rawlog;
  record::RunHeader header;
  sim::MissionConfig mission;  // the header's config, read as `coinspect run` read it
  world::Scenario scenario;

  // The latest mission time an object of this run can carry: the mission clock starts by
  // start_timeout at the latest and runs for the budget; 1 s more for the last tick's records.
  double latestTime() const {
    return mission.startTimeout + mission.budget.value_or(scenario.missionBudget) + 1.0;
  }
};

// Reads the header of `rawlog` and builds its scenario: from `scenarioSource` (a SOURCE as in
// loadScenarioSource, with the header config's scenario_seed and fleet) when it is not empty, else
// from the header config's [mission] scenario. Throws InputError when the rawlog has no coinspect
// header, when the scenario cannot be built (the message suggests --scenario), or when its content
// hash differs from the one recorded.
RecordedRun openRecordedRun(const std::filesystem::path& rawlog, const std::string& scenarioSource);

}  // namespace coinspect::app
