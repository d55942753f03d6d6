#include "coinspect/strategies/coinspect/exploration_layers.h"

#include <algorithm>

#include "coinspect/strategies/runtime/box_geometry.h"

namespace coinspect::strategies::coinspect_strategy {

std::vector<double> explorationLayers(const agent::BoxView& box,
                                      const std::vector<agent::BoxView>& boxes, double lowest,
                                      double roofHeight) {
  const auto bounds = runtime::boxBounds(box);
  const double bottom = std::max(bounds.min.z(), lowest), top = bounds.max.z();
  std::vector<double> layers =
      top - bottom > 20.0
          ? std::vector<double>{bottom + 0.3 * (top - bottom), bottom + 0.75 * (top - bottom)}
          : std::vector<double>{0.5 * (bottom + std::max(bottom, top))};
  const bool covered = std::any_of(boxes.begin(), boxes.end(), [&](const auto& other) {
    const auto b = runtime::boxBounds(other);
    return b.min.z() >= top - 1.0 && b.min.x() < bounds.max.x() && b.max.x() > bounds.min.x() &&
           b.min.y() < bounds.max.y() && b.max.y() > bounds.min.y();
  });
  if (!covered) layers.push_back(top + roofHeight);
  return layers;
}

}  // namespace coinspect::strategies::coinspect_strategy
