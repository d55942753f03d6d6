// PLACEHOLDER: replaced by the real command in this session.
#include "commands.h"

namespace coinspect::app {
void addScoreCommand(CLI::App& root) { root.add_subcommand("score", "(not yet implemented)"); }
}  // namespace coinspect::app
