// How every subcommand turns a SOURCE argument into a scenario.
#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include "coinspect/world/generators.h"
#include "coinspect/world/scenario.h"

namespace coinspect::app {

// SOURCE is, in this order of precedence:
//   - a folder holding box_description.yaml: a reference CARIC scenario (importCaricScenario);
//   - a folder holding scenario.ini, or a path to an .ini file: our own format (loadScenario);
//   - the name of a built-in generator (generateScenario with `seed` and `fleet`).
// Anything else throws InputError naming SOURCE.
world::Scenario loadScenarioSource(const std::string& source, uint64_t seed,
                                   const std::optional<world::SleiFleet>& fleet = {});

}  // namespace coinspect::app
