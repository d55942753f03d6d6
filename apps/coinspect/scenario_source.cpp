#include "scenario_source.h"

#include <filesystem>

#include "coinspect/core/error.h"
#include "coinspect/world/caric_scenario.h"
#include "coinspect/world/generators.h"
#include "coinspect/world/scenario_files.h"

namespace coinspect::app {

world::Scenario loadScenarioSource(const std::string& source, uint64_t seed,
                                   const std::optional<world::SleiFleet>& fleet) {
  namespace fs = std::filesystem;
  const fs::path path(source);
  if (fs::is_directory(path)) {
    if (fs::exists(path / "box_description.yaml")) return world::importCaricScenario(path);
    if (fs::exists(path / "scenario.ini")) return world::loadScenario(path / "scenario.ini");
    throw InputError(source, "",
                     "folder holds neither box_description.yaml (CARIC) nor scenario.ini");
  }
  if (path.extension() == ".ini") return world::loadScenario(path);
  // Not a file: a generator name (generateScenario lists the known names when it is not one).
  return world::generateScenario(source, seed, fleet);
}

}  // namespace coinspect::app
