// Private helpers of the time plots (score.png, the features-over-time picture): a plot area
// with its two axes, its grid, ticks and labels, and step curves drawn in it.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "coinspect/eval/image.h"
#include "plot_axes.h"

namespace coinspect::eval::detail {

// Colours shared by the time plots.
inline constexpr Rgb kPlotBackground{255, 255, 255};
inline constexpr Rgb kPlotText{35, 35, 35};
inline constexpr Rgb kPlotFrame{110, 110, 110};
inline constexpr Rgb kPlotGrid{232, 232, 232};

struct Panel {
  int left, top, right, bottom;  // pixels; the plot area is left <= x < right, top <= y < bottom
  NiceAxis x, y;
  double px(double t) const { return left + (t - x.lo) / (x.hi - x.lo) * (right - 1 - left); }
  double py(double v) const { return bottom - 1 - (v - y.lo) / (y.hi - y.lo) * (bottom - 1 - top); }
};

// Grid, frame, y ticks with labels, the y-axis title; x ticks (labels only when `xLabels`).
void drawPanelAxes(RgbImage& image, const Panel& panel, const std::string& yTitle, bool xLabels,
                   int scale);

// A step curve from (x.lo, 0) through the (time, value) samples, in time order, then level up to
// `endTime`; with `fillBelow`, a light fill of its colour under it (one curve per panel: a fill
// would hide the curves drawn before it).
void drawSteps(RgbImage& image, const Panel& panel,
               const std::vector<std::pair<double, double>>& steps, double endTime, Rgb color,
               int scale, bool fillBelow);

}  // namespace coinspect::eval::detail
