// Each subcommand of the coinspect tool registers itself on the root CLI11 app.
// A command's callback returns normally on success and throws on failure; main() turns
// InputError, and a bad command line, into a one-line message and exit code 2. A command that has
// done its work and printed its results but must end with another status throws CommandStatus.
#pragma once

#include <CLI/CLI.hpp>

namespace coinspect::app {

void addScenarioCommand(CLI::App& root);
void addScoreCommand(CLI::App& root);
void addDemoCommand(CLI::App& root);
void addRunCommand(CLI::App& root);
void addEvalCommand(CLI::App& root);
void addRenderCommand(CLI::App& root);
void addReplayCommand(CLI::App& root);
void addPlotFeaturesCommand(CLI::App& root);
void addPlotTimelineCommand(CLI::App& root);

// Thrown after a command printed its results, to make main() return `status` (eval, render and
// replay: 1 for a damaged rawlog; eval: 3 when the re-scored tally differs from the recorded one).
struct CommandStatus {
  int status = 0;
};

}  // namespace coinspect::app
