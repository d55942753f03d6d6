// The features-over-time picture of feature missions (the SLEI3D paper's Fig. 15): for one stage
// of the feature pipeline (discovered, assigned, inspected, collected), how many features had
// reached it at each moment of the mission, one step curve per run, so that strategies or seeds
// can be compared on one picture. `coinspect plot-features` draws it from the runs' report.json
// (doc/evaluation.md); this library knows nothing of JSON.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "coinspect/eval/image.h"

namespace coinspect::eval {

// One run's curve.
struct FeatureCurve {
  std::string label;          // its legend entry
  std::string scenario;       // for the title
  std::vector<double> times;  // mission clock (s) at which each feature reached the stage, in any
                              // order; finite and >= 0
  uint64_t total = 0;         // features in the scenario: a dashed horizontal line
  double budget = 0.0;        // mission budget (s): the curve goes on up to it (or its last time)
};

// Where the picture put its plot and legend (tests locate content with it): pixel x of a time and
// pixel y of a count, both in pixels (x right, y down).
struct FeaturePlotFrame {
  double timeLo = 0.0, timeHi = 1.0;             // the x axis (s)
  double countLo = 0.0, countHi = 1.0;           // the y axis (features)
  int left = 0, top = 0, right = 0, bottom = 0;  // plot area: left <= x < right, top <= y < bottom
  int legendLeft = 0, legendTop = 0, legendRight = 0, legendBottom = 0;  // empty without curves
  double x(double time) const;
  double y(double count) const;
};

// "features <stage> over time (<scenario>, <total> features)"; several scenarios or totals are
// listed in the order of the curves, "a, b" and "150/200 features".
std::string featurePlotTitle(const std::string& stage, const std::vector<FeatureCurve>& curves);

// The picture: x the mission time from 0 to the latest budget (or event), y the count of
// features from 0 past the largest total; curve i in unitColor(i) with its legend entry right of
// the plot; a grey dashed line at each total. No curves: the empty axes. Same input, same pixels.
RgbImage renderFeaturePlot(const std::string& stage, const std::vector<FeatureCurve>& curves,
                           int width, int height, FeaturePlotFrame* frame = nullptr);

}  // namespace coinspect::eval
