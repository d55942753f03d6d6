#include "coinspect/strategies/builtin.h"

#include "coinspect/strategies/caric_baseline.h"
#include "coinspect/strategies/coinspect/coinspect_strategy.h"
#include "coinspect/strategies/demo_paths.h"

namespace coinspect::strategies {

void registerBuiltinStrategies(agent::StrategyRegistry& registry) {
  registerCaricBaseline(registry);
  registerDemoPaths(registry);
  coinspect_strategy::registerCoinspect(registry);
}

}  // namespace coinspect::strategies
