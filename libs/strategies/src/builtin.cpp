#include "coinspect/strategies/builtin.h"

#include "coinspect/strategies/demo_paths.h"

namespace coinspect::strategies {

void registerBuiltinStrategies(agent::StrategyRegistry& registry) {
  registerDemoPaths(registry);
}

}  // namespace coinspect::strategies
