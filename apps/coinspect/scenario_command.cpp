// PLACEHOLDER: replaced by the real command in this session.
#include "commands.h"

namespace coinspect::app {
void addScenarioCommand(CLI::App& root) { root.add_subcommand("scenario", "(not yet implemented)"); }
}  // namespace coinspect::app
