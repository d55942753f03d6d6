#include "coinspect/strategies/builtin.h"

#include "coinspect/strategies/caric_baseline.h"
#include "coinspect/strategies/coinspect/coinspect_strategy.h"
#include "coinspect/strategies/demo_paths.h"
#include "coinspect/strategies/kios/kios_strategy.h"
#include "coinspect/strategies/slei/slei3d_strategy.h"
#include "coinspect/strategies/star/star_strategy.h"

namespace coinspect::strategies {

void registerBuiltinStrategies(agent::StrategyRegistry& registry) {
  registerCaricBaseline(registry);
  registerDemoPaths(registry);
  coinspect_strategy::registerCoinspect(registry);
  kios::registerKios(registry);
  star::registerStar(registry);
  slei::registerSlei3d(registry);
}

}  // namespace coinspect::strategies
