// score.png: two panels over the same time axis, Q above and detected points below.
#include <algorithm>
#include <cinttypes>
#include <cmath>
#include <cstdio>
#include <limits>

#include "coinspect/eval/bitmap_font.h"
#include "coinspect/eval/canvas.h"
#include "coinspect/eval/run_plots.h"
#include "coinspect/record/observations.h"
#include "plot_panel.h"

namespace coinspect::eval {

namespace {

using detail::Panel;

constexpr Rgb kScoreColor{31, 119, 180};
constexpr Rgb kDetectedColor{215, 110, 20};
constexpr Rgb kMissionEventColor{120, 120, 120};
constexpr Rgb kDeathColor{190, 30, 30};

struct EventMark {
  double time;
  std::string label;
  Rgb color;
};

// The start and end of the mission clock, and the first death of each unit.
std::vector<EventMark> eventMarks(const RunTracks& tracks) {
  std::vector<EventMark> marks;
  for (const auto& event : tracks.events) {
    using K = record::MissionEventKind;
    if (event.kind == K::Start || event.kind == K::End)
      marks.push_back({event.time, eventKindName(event.kind), kMissionEventColor});
  }
  for (const auto& unit : tracks.units)
    if (unit.deathTime) marks.push_back({*unit.deathTime, unit.name + " lost", kDeathColor});
  std::stable_sort(marks.begin(), marks.end(),
                   [](const EventMark& a, const EventMark& b) { return a.time < b.time; });
  return marks;
}

// Rows of event labels kept free above the upper panel.
constexpr int kLabelRows = 2;
int labelRowHeight(int scale) {
  return textHeight(scale) + 3 * scale;
}

// Dashed lines through both panels, each labelled in the band above the upper panel (row 0
// right above it); a label that would overlap others in every row is left out, its line stays.
void drawEventMarks(RgbImage& image, const Panel& upper, const Panel& lower,
                    const std::vector<EventMark>& marks, int scale) {
  std::vector<int> rowEnd(kLabelRows, std::numeric_limits<int>::min());
  for (const auto& mark : marks) {
    const double x = upper.px(mark.time);
    drawDashedLine(image, x, upper.top, x, upper.bottom, 4 * scale, 3 * scale, mark.color);
    drawDashedLine(image, x, lower.top, x, lower.bottom, 4 * scale, 3 * scale, mark.color);
    const int width = textWidth(mark.label, scale);
    const int left = std::clamp(static_cast<int>(x) - width / 2, upper.left - 4 * scale,
                                upper.right + 4 * scale - width);
    for (int row = 0; row < kLabelRows; ++row) {
      if (left <= rowEnd[row]) continue;
      const int y = upper.top - (row + 1) * labelRowHeight(scale);
      drawDashedLine(image, x, y + textHeight(scale), x, upper.top, 2 * scale, 2 * scale,
                     mark.color);
      drawText(image, left, y, mark.label, mark.color, scale);
      rowEnd[row] = left + width + 4 * scale;
      break;
    }
  }
}

}  // namespace

RgbImage renderScorePlot(const RunTracks& tracks, const std::string& name, int width, int height) {
  RgbImage image(width, height, detail::kPlotBackground);
  const int s = labelScale(width, height);
  const int pad = 8 * s;

  char title[256];
  if (tracks.pointCount > 0)
    std::snprintf(title, sizeof(title),
                  "%s: score Q = %.2f, detected %" PRIu64 " / %" PRIu64 " points", name.c_str(),
                  tracks.finalScore(), tracks.finalDetected(), tracks.pointCount);
  else
    std::snprintf(title, sizeof(title), "%s: no ground-station tally recorded", name.c_str());
  drawText(image, width / 2, pad, title, detail::kPlotText, s, TextAlign::Center);

  double maxScore = 0.0;
  uint64_t maxDetected = 0;
  std::vector<std::pair<double, double>> scoreSteps, detectedSteps;
  for (const auto& sample : tracks.tally) {
    maxScore = std::max(maxScore, sample.totalScore);
    maxDetected = std::max(maxDetected, sample.detected);
    scoreSteps.emplace_back(sample.time, sample.totalScore);
    detectedSteps.emplace_back(sample.time, static_cast<double>(sample.detected));
  }
  const double endTime = std::max(tracks.endTime, 1e-3);

  Panel upper{}, lower{};
  upper.y = detail::niceAxis(0.0, std::max(maxScore, 1.0), 5, true);
  lower.y = detail::niceAxis(0.0, std::max<double>(static_cast<double>(maxDetected), 1.0), 5, true);
  int labelWidth = 0;
  for (const auto* axis : {&upper.y, &lower.y})
    for (double v : axis->ticks)
      labelWidth = std::max(labelWidth, textWidth(detail::tickLabel(v, axis->decimals), s));
  const int left = 4 * s + textHeight(s) + pad + labelWidth + 7 * s;
  const int right = width - pad - 3 * s * kGlyphAdvance;  // room for the last time label
  const int top = pad + textHeight(s) + pad + kLabelRows * labelRowHeight(s) + 2 * s;
  const int bottom = height - (pad + 2 * textHeight(s) + 10 * s);
  const int gap = 3 * pad;
  const int panelHeight = std::max(1, (bottom - top - gap) / 2);
  upper.left = lower.left = left;
  upper.right = lower.right = std::max(left + 1, right);
  upper.top = top;
  upper.bottom = top + panelHeight;
  lower.top = upper.bottom + gap;
  lower.bottom = lower.top + panelHeight;
  upper.x = lower.x =
      detail::niceAxis(0.0, endTime, std::max(2, (upper.right - left) / (70 * s)), false);

  detail::drawPanelAxes(image, upper, "score Q", false, s);
  detail::drawPanelAxes(image, lower, "detected points", true, s);
  detail::drawSteps(image, upper, scoreSteps, upper.x.hi, kScoreColor, s, true);
  detail::drawSteps(image, lower, detectedSteps, lower.x.hi, kDetectedColor, s, true);
  drawEventMarks(image, upper, lower, eventMarks(tracks), s);
  // Frames again: the fills and curves must not hide them.
  strokeRect(image, upper.left - 1, upper.top - 1, upper.right + 1, upper.bottom + 1,
             detail::kPlotFrame);
  strokeRect(image, lower.left - 1, lower.top - 1, lower.right + 1, lower.bottom + 1,
             detail::kPlotFrame);
  drawText(image, (left + upper.right) / 2, lower.bottom + 6 * s + textHeight(s) + 4 * s,
           "mission time (s)", detail::kPlotText, s, TextAlign::Center);
  return image;
}

}  // namespace coinspect::eval
