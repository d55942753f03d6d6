// Splitting the inspection work between robots without talking: every robot runs the same
// deterministic computation on common knowledge (the mission's boxes and the fleet roster), so
// all agree on who inspects what. Work items are samples of the box faces weighted by area; the
// split is a recursive bisection along the longest extent, in proportion to each robot's
// capacity (an explorer, busy mapping first, gets less), so each region is compact.
#pragma once

#include <cstdint>
#include <vector>

#include "coinspect/agent/observations.h"

namespace coinspect::strategies::coinspect_strategy {

using agent::Vec3;

struct WorkItem {
  Vec3 position = Vec3::Zero();  // a point of a box face
  Vec3 normal = Vec3::UnitZ();   // outward normal of that face
  double weight = 1.0;           // m^2 of face it stands for
};

// Samples every box face on a grid of about `spacing` m; faces whose outward normal points down
// and that lie within `groundClearance` of `groundZ` are skipped (nothing inspects a floor).
std::vector<WorkItem> sampleBoxFaces(const std::vector<agent::BoxView>& boxes, double spacing,
                                     double groundZ, double groundClearance);

// Region index (0..capacities.size()-1) of every item: region r gets about capacities[r] /
// sum(capacities) of the total weight. Capacities must be positive.
std::vector<uint32_t> partitionWork(const std::vector<WorkItem>& items,
                                    const std::vector<double>& capacities);

}  // namespace coinspect::strategies::coinspect_strategy
