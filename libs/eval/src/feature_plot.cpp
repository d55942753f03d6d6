// The features-over-time picture: one panel laid out like score.png's, the legend right of it as
// in the plan views.
#include "coinspect/eval/feature_plot.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "coinspect/core/error.h"
#include "coinspect/eval/bitmap_font.h"
#include "coinspect/eval/canvas.h"
#include "coinspect/eval/run_plots.h"
#include "legend.h"
#include "plot_panel.h"

namespace coinspect::eval {

namespace {

constexpr Rgb kTotalLineColor{120, 120, 120};
// Room above the highest total or count (a fraction of it), so that the total's dashed line and
// its label stay inside the plot instead of on its frame.
constexpr double kHeadroom = 0.08;
// Smallest top of the count axis: below 5 the axis would step by halves, not whole features.
constexpr double kMinCountTop = 5.0;

detail::Panel panelOf(const FeaturePlotFrame& frame) {
  detail::Panel panel{frame.left, frame.top, frame.right, frame.bottom, {}, {}};
  panel.x.lo = frame.timeLo;
  panel.x.hi = frame.timeHi;
  panel.y.lo = frame.countLo;
  panel.y.hi = frame.countHi;
  return panel;
}

// (time, count) at each time the count grows: the k-th sorted time brings it to k, and features
// reaching the stage at the same time make one step.
std::vector<std::pair<double, double>> countSteps(std::vector<double> times) {
  std::sort(times.begin(), times.end());
  std::vector<std::pair<double, double>> steps;
  for (size_t i = 0; i < times.size(); ++i)
    if (i + 1 == times.size() || times[i + 1] != times[i])
      steps.emplace_back(times[i], static_cast<double>(i + 1));
  return steps;
}

// Where a curve stops: its budget, or its last event when that came later.
double curveEnd(const FeatureCurve& curve) {
  double end = curve.budget;
  for (double t : curve.times)
    end = std::max(end, t);
  return end;
}

// The distinct values of `key` over the curves, in the order of the curves.
template <typename Value, typename Key>
std::vector<Value> distinct(const std::vector<FeatureCurve>& curves, Key key) {
  std::vector<Value> values;
  for (const auto& curve : curves) {
    const Value value = key(curve);
    if (std::find(values.begin(), values.end(), value) == values.end()) values.push_back(value);
  }
  return values;
}

std::vector<uint64_t> distinctTotals(const std::vector<FeatureCurve>& curves) {
  return distinct<uint64_t>(curves, [](const FeatureCurve& c) { return c.total; });
}

void drawTotalLines(RgbImage& image, const detail::Panel& panel,
                    const std::vector<FeatureCurve>& curves, int scale) {
  for (const uint64_t total : distinctTotals(curves)) {
    const double y = std::round(panel.py(static_cast<double>(total)));
    drawDashedLine(image, panel.left, y, panel.right - 1, y, 6 * scale, 4 * scale, kTotalLineColor);
    drawText(image, panel.right - 4 * scale, static_cast<int>(y) - (kGlyphCapHeight + 3) * scale,
             std::to_string(total) + " features", kTotalLineColor, scale, TextAlign::Right);
  }
}

}  // namespace

double FeaturePlotFrame::x(double time) const {
  return panelOf(*this).px(time);
}

double FeaturePlotFrame::y(double count) const {
  return panelOf(*this).py(count);
}

namespace {

// "priority" is the collection of the high-priority features ([features] priority_boxes).
std::string stageLabel(const std::string& stage) {
  return stage == "priority" ? "collected (high priority)" : stage;
}

}  // namespace

std::string featurePlotTitle(const std::string& stage, const std::vector<FeatureCurve>& curves) {
  std::string title = "features " + stageLabel(stage) + " over time (";
  if (curves.empty()) return title + "no runs)";
  for (const auto& scenario :
       distinct<std::string>(curves, [](const FeatureCurve& c) { return c.scenario; }))
    if (!scenario.empty()) title += scenario + ", ";
  const auto totals = distinctTotals(curves);
  for (size_t i = 0; i < totals.size(); ++i)
    title += (i > 0 ? "/" : "") + std::to_string(totals[i]);
  return title + " features)";
}

RgbImage renderFeaturePlot(const std::string& stage, const std::vector<FeatureCurve>& curves,
                           int width, int height, FeaturePlotFrame* frameOut) {
  double endTime = 0.0, topCount = 0.0;
  for (const auto& curve : curves) {
    COINSPECT_ASSERT(std::isfinite(curve.budget) && curve.budget >= 0.0);
    for (double t : curve.times)
      COINSPECT_ASSERT(std::isfinite(t) && t >= 0.0);
    endTime = std::max(endTime, curveEnd(curve));
    topCount = std::max(
        {topCount, static_cast<double>(curve.total), static_cast<double>(curve.times.size())});
  }

  RgbImage image(width, height, detail::kPlotBackground);
  const int s = labelScale(width, height);
  const int pad = 8 * s;
  drawText(image, width / 2, pad, featurePlotTitle(stage, curves), detail::kPlotText, s,
           TextAlign::Center);

  std::vector<detail::LegendEntry> legend;
  for (size_t i = 0; i < curves.size(); ++i)
    legend.push_back({detail::LegendEntry::Kind::Line, curves[i].label, unitColor(i)});

  detail::Panel panel{};
  panel.y = detail::niceAxis(0.0, std::max(kMinCountTop, (1.0 + kHeadroom) * topCount), 5, true);
  int labelWidth = 0;
  for (double v : panel.y.ticks)
    labelWidth = std::max(labelWidth, textWidth(detail::tickLabel(v, panel.y.decimals), s));
  panel.left = 4 * s + textHeight(s) + pad + labelWidth + 7 * s;
  panel.top = pad + textHeight(s) + pad;
  // With a legend, it takes the right side (as in the plan views); without, keep room for the
  // last time label (as in score.png).
  const int right = legend.empty() ? width - pad - 3 * s * kGlyphAdvance
                                   : width - 2 * pad - detail::legendWidth(legend, s);
  panel.right = std::max(panel.left + 16, right);
  panel.bottom = std::max(panel.top + 16, height - (pad + 2 * textHeight(s) + 10 * s));
  panel.x =
      detail::niceAxis(0.0, endTime, std::max(2, (panel.right - panel.left) / (70 * s)), false);

  detail::drawPanelAxes(image, panel, "features " + stageLabel(stage), true, s);
  drawTotalLines(image, panel, curves, s);
  // No fill under the curves: it would hide the curves drawn before.
  for (size_t i = 0; i < curves.size(); ++i)
    detail::drawSteps(image, panel, countSteps(curves[i].times), curveEnd(curves[i]), unitColor(i),
                      s, false);
  // The frame again: the curves at 0 and at the end of the axis must not hide it.
  strokeRect(image, panel.left - 1, panel.top - 1, panel.right + 1, panel.bottom + 1,
             detail::kPlotFrame);
  drawText(image, (panel.left + panel.right) / 2, panel.bottom + 6 * s + textHeight(s) + 4 * s,
           "mission time (s)", detail::kPlotText, s, TextAlign::Center);

  FeaturePlotFrame frame;
  frame.timeLo = panel.x.lo;
  frame.timeHi = panel.x.hi;
  frame.countLo = panel.y.lo;
  frame.countHi = panel.y.hi;
  frame.left = panel.left;
  frame.top = panel.top;
  frame.right = panel.right;
  frame.bottom = panel.bottom;
  if (!legend.empty())
    detail::drawLegendInFrame(image, panel.right + pad, panel.top, legend, s, frame);
  if (frameOut) *frameOut = frame;
  return image;
}

}  // namespace coinspect::eval
