// [energy]: batteries drain while airborne and charge near a live ground station (SLEI3D's
// energy limits, doc/features.md "Energy"). Updated at the monitor rate, on the mission clock.
#include <algorithm>
#include <cstdio>
#include <string>

#include "mission_impl.h"

namespace coinspect::sim {

namespace {

std::string percent(double level) {
  char text[32];
  std::snprintf(text, sizeof text, "%.0f %%", 100.0 * level);
  return text;
}

}  // namespace

void Mission::Impl::updateEnergy(double dt) {
  for (size_t i = 0; i < units.size(); ++i) {
    auto& unit = units[i];
    if (!unit.battery.limited() || !unit.alive()) continue;
    const auto& position = unit.vehicle->state().position;
    // The charger is contactless within the range: a UAV need not land on the station (which
    // may be driving) to charge; while it charges it does not drain.
    const bool atCharger = std::any_of(stations.begin(), stations.end(), [&](size_t s) {
      return units[s].alive() &&
             (units[s].state().position - position).norm() <= unit.battery.chargeRange;
    });
    if (atCharger && unit.energy < 1.0) {
      if (!unit.charging) event("charge-start", unit.spec->name, percent(unit.energy));
      unit.charging = true;
      unit.energy = std::min(1.0, unit.energy + dt / unit.battery.chargeTime);
      unit.chargedFor += dt;
      continue;
    }
    if (unit.charging) event("charge-end", unit.spec->name, percent(unit.energy));
    unit.charging = false;
    if (atCharger || !unit.vehicle->airborne()) continue;
    unit.energy = std::max(0.0, unit.energy - dt / unit.battery.capacity);
    unit.lowestEnergy = std::min(unit.lowestEnergy, unit.energy);
    if (unit.energy <= 0.0) kill(i, "battery empty");
  }
}

}  // namespace coinspect::sim
