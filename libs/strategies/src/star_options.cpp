#include "coinspect/strategies/star/star_options.h"

#include <cmath>
#include <string>

#include "coinspect/core/error.h"
#include "coinspect/strategies/runtime/option_reader.h"

namespace coinspect::strategies::star {

namespace {

const char* const kSection = "star";

double readDouble(const Config& config, const std::string& key, double fallback, double low,
                  double high, const std::string& range) {
  return runtime::readNumber(config, kSection, key, fallback, low, high, range);
}

}  // namespace

StarOptions StarOptions::read(const Config& config) {
  StarOptions o;
  o.maxSpeed = readDouble(config, "max_speed", o.maxSpeed, 0.1, 20.0, "in [0.1, 20] m/s");
  o.viewDistance =
      readDouble(config, "view_distance", o.viewDistance, 0.3, 1.5, "in [0.3, 1.5] (a fraction)");
  o.replanPeriod =
      readDouble(config, "replan_period", o.replanPeriod, 0.5, 120.0, "in [0.5, 120] s");
  o.frontierMargin =
      readDouble(config, "frontier_margin", o.frontierMargin, 0.5, 50.0, "in [0.5, 50] m");
  o.clusterRadius =
      readDouble(config, "cluster_radius", o.clusterRadius, 0.5, 100.0, "in [0.5, 100] m");
  o.yawWeight = readDouble(config, "yaw_weight", o.yawWeight, 0.0, 100.0, "in [0, 100] m/rad");
  o.broadcastPeriod =
      readDouble(config, "broadcast_period", o.broadcastPeriod, 0.1, 600.0, "in [0.1, 600] s");
  o.explorersInspect = config.getBool(kSection, "explorers_inspect", o.explorersInspect);
  o.returnHome = config.getBool(kSection, "return_home", o.returnHome);
  return o;
}

}  // namespace coinspect::strategies::star
