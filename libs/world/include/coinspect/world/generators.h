// Scenario generators that need no external data, deterministic by seed.
#pragma once

#include <cstdint>
#include <optional>
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
// Their names in that order, separated by ", " (for error messages that list them).
std::string generatorNames();

// The size of a SLEI fleet: the paper's scenes fly 1 + 2 + 4 (A, B), 1 + 4 + 8 (C), 1 + 8 + 40
// (D), its scale test 5 + 10 + 60.
struct SleiFleet {
  int stations = 1;
  int explorers = 2;
  int inspectors = 4;
};
// What is wrong with a fleet size (1 to 20 stations, 1 to 100 explorers, 0 to 400 inspectors),
// as a sentence; empty when nothing is.
std::string sleiFleetProblem(const SleiFleet& fleet);

// Generates the named scenario; same name, seed and fleet give the same scenario (same
// contentHash). `fleet` replaces a slei-* scene's own fleet (same layout at the site's gate; the
// scene and its features do not change). Throws InputError("scenario", name, ...) listing the
// known names for an unknown one, and for a fleet given to a caric generator or out of range
// (sleiFleetProblem).
Scenario generateScenario(const std::string& name, uint64_t seed = 1,
                          const std::optional<SleiFleet>& fleet = {});

}  // namespace coinspect::world
