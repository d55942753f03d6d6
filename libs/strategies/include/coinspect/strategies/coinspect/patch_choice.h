// Which surface patches an inspection plan covers. The robot's own region first (the work
// partition's answer for the patch); when nothing of it is left that nobody reported done, the
// remaining patches of every region: a robot that finished helps the others, and the region of
// a robot that failed (which reports nothing any more) is taken over. At most `max` patches,
// nearest to the robot first, because the set cover grows with candidates x patches and a plan
// flies only a few viewpoints anyway.
#pragma once

#include <cstdint>
#include <functional>
#include <vector>

#include "coinspect/agent/observations.h"
#include "coinspect/planning/coverage.h"

namespace coinspect::strategies::coinspect_strategy {

// `owners[i]`: region of `patches[i]`; `done(key)`: viewed by this robot or reported by others.
std::vector<planning::InspectionPatch> choosePatches(
    const std::vector<planning::InspectionPatch>& patches, const std::vector<uint32_t>& owners,
    uint32_t region, const std::function<bool(uint64_t)>& done, const agent::Vec3& here,
    size_t max);

}  // namespace coinspect::strategies::coinspect_strategy
