// Each subcommand of the coinspect tool registers itself on the root CLI11 app.
// A command's callback returns normally on success and throws on failure; main() turns
// InputError into a one-line message and exit code 2.
#pragma once

#include <CLI/CLI.hpp>

namespace coinspect::app {

void addScenarioCommand(CLI::App& root);
void addScoreCommand(CLI::App& root);
void addDemoCommand(CLI::App& root);
void addRunCommand(CLI::App& root);

}  // namespace coinspect::app
