// How a scenario named by a user (a mission's `[mission] scenario`, a subcommand's SOURCE) is
// found: one rule for every entry point, so a name means the same scenario everywhere.
#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include "coinspect/world/generators.h"
#include "coinspect/world/scenario.h"

namespace coinspect::world {

// True when `source` is exactly the name of a built-in generator ("mbs", "slei-c", ...).
bool isGeneratorName(const std::string& source);

// `source` is, in this order of precedence:
//   - exactly the name of a built-in generator: generateScenario(source, seed, fleet). A name
//     is never looked up on disk first: an output folder named after its scenario (`--out
//     slei-c`) would otherwise hide the generator for every later run or replay from that
//     folder. A folder of that name is given as ./slei-c;
//   - a folder holding box_description.yaml: a reference CARIC scenario (importCaricScenario);
//   - a folder holding scenario.ini, or a scenario file: our own format (loadScenario).
// A fleet size is only for a generator. Anything else throws InputError(origin, key, ...)
// naming `source` (origin empty: `source` itself).
Scenario loadScenarioSource(const std::string& source, uint64_t seed,
                            const std::optional<SleiFleet>& fleet = {},
                            const std::string& origin = "", const std::string& key = "");

}  // namespace coinspect::world
