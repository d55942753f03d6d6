// Registers every strategy shipped with coinspect (explicitly: no static-initialiser magic).
#pragma once

#include "coinspect/agent/strategy.h"

namespace coinspect::strategies {

void registerBuiltinStrategies(agent::StrategyRegistry& registry);

}  // namespace coinspect::strategies
