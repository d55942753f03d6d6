// The side outputs of `coinspect run --out DIR` (doc/config.md, "Outputs"): poses recorded
// during the run, then summary.txt, events.csv, score.csv and report.json at the end.
#pragma once

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "coinspect/core/config.h"
#include "coinspect/record/tum_trajectory.h"
#include "coinspect/sim/mission.h"

namespace coinspect::app {

class RunOutputs {
 public:
  // Creates `folder` and one <unit>.tum per unit, and hooks the writers to the mission's
  // controller tick (20 Hz of simulated time).
  RunOutputs(sim::Mission& mission, std::filesystem::path folder);
  // Writes the end-of-run files. `ini` is the resolved config, `configFile` its path.
  void finish(const sim::Mission& mission, const Config& ini, const std::string& configFile,
              const std::string& summaryText);

 private:
  std::filesystem::path folder_;
  std::vector<record::TumTrajectoryWriter> trajectories_;
};

}  // namespace coinspect::app
