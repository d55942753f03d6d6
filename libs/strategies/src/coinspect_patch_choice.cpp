#include "coinspect/strategies/coinspect/patch_choice.h"

#include <algorithm>

#include "coinspect/core/error.h"

namespace coinspect::strategies::coinspect_strategy {

std::vector<planning::InspectionPatch> choosePatches(
    const std::vector<planning::InspectionPatch>& patches, const std::vector<uint32_t>& owners,
    uint32_t region, const std::function<bool(uint64_t)>& done, const agent::Vec3& here,
    size_t max) {
  COINSPECT_ASSERT(owners.size() == patches.size());
  std::vector<planning::InspectionPatch> own, others;
  for (size_t i = 0; i < patches.size(); ++i) {
    if (done(patches[i].key)) continue;
    (owners[i] == region ? own : others).push_back(patches[i]);
  }
  auto chosen = own.empty() ? std::move(others) : std::move(own);
  if (chosen.size() > max) {
    std::partial_sort(chosen.begin(), chosen.begin() + static_cast<long>(max), chosen.end(),
                      [&](const auto& a, const auto& b) {
                        const double da = (a.centre - here).squaredNorm();
                        const double db = (b.centre - here).squaredNorm();
                        return da != db ? da < db : a.key < b.key;
                      });
    chosen.resize(max);
  }
  return chosen;
}

}  // namespace coinspect::strategies::coinspect_strategy
