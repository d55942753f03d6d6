// The heights at which an explorer orbits a box: one layer at mid-height, or two (30 % and 75 %
// of the height) when the box is taller than 20 m, plus one `roofHeight` above its roof when no
// other box covers that roof (the LiDAR never maps a roof from the side: on CARIC MBS none of the
// sky deck's 355 roof points was detected before this layer). A roof is covered only by a box
// that starts at most 1 m below it and overlaps it horizontally. On CARIC MBS the sky deck's box
// starts 4-6 m below the towers' tops, so each tower still gets a layer 3 m above its top, which
// runs inside the deck's box along the deck's sides: counting the deck as covering the towers
// and dropping those layers lowered seeds 1 and 4 from 1267.21 and 1238.06 to 1123.33 and 1127.30
// (2026-11-24).
#pragma once

#include <vector>

#include "coinspect/agent/observations.h"

namespace coinspect::strategies::coinspect_strategy {

// `lowest`: no layer below this height (the take-off height above the ground).
std::vector<double> explorationLayers(const agent::BoxView& box,
                                      const std::vector<agent::BoxView>& boxes, double lowest,
                                      double roofHeight);

}  // namespace coinspect::strategies::coinspect_strategy
