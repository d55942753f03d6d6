// Private helpers of the plots: "nice" axis ticks and their labels.
#pragma once

#include <string>
#include <vector>

namespace coinspect::eval::detail {

struct NiceAxis {
  double lo = 0.0, hi = 1.0;  // the range shown
  double step = 1.0;          // 1, 2 or 5 times a power of ten
  int decimals = 0;           // digits after the point that the labels need
  std::vector<double> ticks;  // multiples of step within [lo, hi]
};

// Ticks for [lo, hi] at most about `maxTicks` apart. When `extendToTicks`, the range grows to
// the enclosing multiples of the step (plots of values from 0); otherwise it is kept.
NiceAxis niceAxis(double lo, double hi, int maxTicks, bool extendToTicks);

// A tick label: the value with the axis's decimals ("-0" printed as "0").
std::string tickLabel(double value, int decimals);

}  // namespace coinspect::eval::detail
