// Options of the `star` strategy, section [star] (every key optional; doc/config.md).
#pragma once

#include "coinspect/core/config.h"

namespace coinspect::strategies::star {

struct StarOptions {
  double maxSpeed = 3.0;         // m/s: explorers and transit (photographers keep q_blur = 1)
  double viewDistance = 0.8;     // fraction of the camera's q_res = 1 distance for viewpoints
  double replanPeriod = 4.0;     // s between plans (receding horizon)
  double frontierMargin = 4.0;   // m: frontier cells farther from every box are ignored
  double clusterRadius = 6.0;    // m: inspection viewpoints within this (and in sight) cluster
  double yawWeight = 2.0;        // m of travel one radian of heading change costs in the ATSP
  double broadcastPeriod = 2.0;  // s between "star/inspected" broadcasts
  bool explorersInspect = true;  // explorers inspect once no frontier is left near the boxes
  bool returnHome = true;        // be back in sight of the start when the time runs out

  // Reads [star]; throws InputError naming the file and key for a bad value.
  static StarOptions read(const Config& config);
};

}  // namespace coinspect::strategies::star
