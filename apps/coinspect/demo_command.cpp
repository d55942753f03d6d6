// PLACEHOLDER: replaced by the real command in this session.
#include "commands.h"

namespace coinspect::app {
void addDemoCommand(CLI::App& root) { root.add_subcommand("demo", "(not yet implemented)"); }
}  // namespace coinspect::app
