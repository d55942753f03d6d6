// The outputs of `coinspect run --out DIR` (doc/config.md, "Outputs"): run.rawlog and the poses
// recorded during the run, then summary.txt, events.csv, score.csv and report.json at the end.
#pragma once

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "coinspect/core/config.h"
#include "coinspect/record/run_header.h"
#include "coinspect/record/tum_trajectory.h"
#include "coinspect/sim/mission.h"

namespace coinspect::app {

// The run header of a rawlog: this build's version, the run's seed, the scenario's content
// hash (16 lowercase hex digits) and the resolved config (after --set) as INI text, with the
// [mission] scenario, airframes and lidars paths that were relative to the INI's folder made
// relative to `runFolder`, where the rawlog is (eval, render and replay read them from there).
record::RunHeader makeRunHeader(const sim::Mission& mission, const Config& ini,
                                const std::filesystem::path& runFolder);

class RunOutputs {
 public:
  // Creates `folder` (InputError naming it when that fails) and one <unit>.tum per unit, hooks
  // the writers to the mission's controller tick (20 Hz of simulated time) and, unless
  // [record] rawlog = false, starts recording to folder/run.rawlog with the header of
  // makeRunHeader(mission, ini, folder). Call before the mission's first step.
  RunOutputs(sim::Mission& mission, std::filesystem::path folder, const Config& ini);
  // Writes the end-of-run files. `ini` is the resolved config, `configFile` its path.
  void finish(const sim::Mission& mission, const Config& ini, const std::string& configFile,
              const std::string& summaryText);

 private:
  std::filesystem::path folder_;
  std::vector<record::TumTrajectoryWriter> trajectories_;
};

}  // namespace coinspect::app
