// The real CARIC MBS scenario and its ray caster, built once per benchmark program from
// COINSPECT_SHARED_DIR/data/caric-mbs; null when that data is absent (the benchmark then skips).
#pragma once

#include <filesystem>
#include <memory>

#include "coinspect/world/caric_scenario.h"
#include "coinspect/world/ray_caster.h"

namespace coinspect::bench {

struct CaricMbs {
  world::Scenario scenario;
  std::unique_ptr<world::RayCaster> caster;
};

inline const CaricMbs* caricMbs() {
  static const std::unique_ptr<CaricMbs> instance = []() -> std::unique_ptr<CaricMbs> {
    const std::filesystem::path dir =
        std::filesystem::path(COINSPECT_SHARED_DIR) / "data" / "caric-mbs";
    if (!std::filesystem::exists(dir / "mbs.stl")) return nullptr;
    auto mbs = std::make_unique<CaricMbs>();
    mbs->scenario = world::importCaricScenario(dir);
    mbs->caster = std::make_unique<world::RayCaster>(mbs->scenario.meshes, mbs->scenario.groundZ);
    return mbs;
  }();
  return instance.get();
}

}  // namespace coinspect::bench
