// Scenario generators that need no external data, deterministic by seed.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "coinspect/world/scenario.h"

namespace coinspect::world {

struct GeneratorInfo {
  std::string name;         // e.g. "mbs"
  std::string family;       // "caric" or "slei"
  std::string description;  // one line
};

// All generators, in a fixed order.
const std::vector<GeneratorInfo>& scenarioGenerators();

// Generates the named scenario; same name and seed give the same scenario (same contentHash).
// Throws InputError("scenario", name, ...) listing the known names for an unknown one.
Scenario generateScenario(const std::string& name, uint64_t seed = 1);

}  // namespace coinspect::world
