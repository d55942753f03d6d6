#include "coinspect/comms/neighbour_odometry.h"

#include "coinspect/core/error.h"

namespace coinspect::comms {

std::vector<UnitOdometry> neighbourOdometry(uint32_t unit, const LinkMatrix& links,
                                            const std::vector<bool>& alive,
                                            const std::vector<UnitOdometry>& all) {
  COINSPECT_ASSERT(unit < links.size());
  COINSPECT_ASSERT(alive.size() == links.size() && all.size() == links.size());
  std::vector<UnitOdometry> seen;
  if (!alive[unit]) return seen;
  for (uint32_t j : links.neighbours(unit))
    if (alive[j]) seen.push_back(all[j]);
  return seen;
}

}  // namespace coinspect::comms
