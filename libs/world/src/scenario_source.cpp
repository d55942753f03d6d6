#include "coinspect/world/scenario_source.h"

#include <filesystem>

#include "coinspect/core/error.h"
#include "coinspect/world/caric_scenario.h"
#include "coinspect/world/scenario_files.h"

namespace coinspect::world {

bool isGeneratorName(const std::string& source) {
  for (const auto& generator : scenarioGenerators())
    if (generator.name == source) return true;
  return false;
}

Scenario loadScenarioSource(const std::string& source, uint64_t seed,
                            const std::optional<SleiFleet>& fleet, const std::string& origin,
                            const std::string& key) {
  namespace fs = std::filesystem;
  if (isGeneratorName(source)) return generateScenario(source, seed, fleet);
  const std::string from = origin.empty() ? source : origin;
  const fs::path path(source);
  const bool folder = fs::is_directory(path);
  if (!folder && !fs::is_regular_file(path)) {
    throw InputError(
        from, key,
        source + " is neither a file, a folder nor a generator (known: " + generatorNames() + ")");
  }
  if (fleet)
    throw InputError(
        from, key.empty() ? "fleet" : key,
        "a fleet size is only for a generated slei-* scenario, not the files of " + source);
  if (!folder) return loadScenario(path);
  if (fs::exists(path / "box_description.yaml")) return importCaricScenario(path);
  if (fs::exists(path / "scenario.ini")) return loadScenario(path / "scenario.ini");
  throw InputError(
      from, key,
      "the folder " + source + " holds neither box_description.yaml (CARIC) nor scenario.ini");
}

}  // namespace coinspect::world
