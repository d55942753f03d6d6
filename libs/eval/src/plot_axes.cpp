#include "plot_axes.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace coinspect::eval::detail {

NiceAxis niceAxis(double lo, double hi, int maxTicks, bool extendToTicks) {
  NiceAxis axis;
  if (!std::isfinite(lo) || !std::isfinite(hi)) lo = 0.0, hi = 1.0;
  if (!(hi > lo)) hi = lo + 1.0;
  const double raw = (hi - lo) / std::max(maxTicks, 1);
  const double magnitude = std::pow(10.0, std::floor(std::log10(raw)));
  const double normalized = raw / magnitude;
  const double factor = normalized <= 1.0   ? 1.0
                        : normalized <= 2.0 ? 2.0
                        : normalized <= 5.0 ? 5.0
                                            : 10.0;
  axis.step = factor * magnitude;
  axis.decimals = std::max(0, -static_cast<int>(std::floor(std::log10(axis.step) + 1e-9)));
  const double first = std::ceil(lo / axis.step - 1e-9), last = std::floor(hi / axis.step + 1e-9);
  if (extendToTicks) {
    lo = std::min(lo, std::floor(lo / axis.step + 1e-9) * axis.step);
    hi = std::max(hi, std::ceil(hi / axis.step - 1e-9) * axis.step);
  }
  axis.lo = lo;
  axis.hi = hi;
  const double end = extendToTicks ? std::round(hi / axis.step) : last;
  const double begin = extendToTicks ? std::round(lo / axis.step) : first;
  for (double k = begin; k <= end; k += 1.0)
    axis.ticks.push_back(k * axis.step);
  return axis;
}

std::string tickLabel(double value, int decimals) {
  char text[64];
  std::snprintf(text, sizeof(text), "%.*f", decimals, value);
  std::string label = text;
  // "-0", "-0.0": a rounding artefact, not a negative number.
  if (label[0] == '-' && label.find_first_not_of("-0.") == std::string::npos) label.erase(0, 1);
  return label;
}

}  // namespace coinspect::eval::detail
