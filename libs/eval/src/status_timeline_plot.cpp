// The status timeline picture: rows of activity segments laid out like the other time plots
// (title above, time axis below, legend right of the plot as in feature_plot.cpp).
#include <algorithm>
#include <cmath>

#include "coinspect/eval/bitmap_font.h"
#include "coinspect/eval/canvas.h"
#include "coinspect/eval/run_plots.h"
#include "coinspect/eval/status_timeline.h"
#include "legend.h"
#include "plot_panel.h"

namespace coinspect::eval {

namespace {

// The bar of segments fills this fraction of its row: the gaps between bars keep rows apart.
constexpr double kBarFraction = 0.55;

int pixel(double v) {
  return static_cast<int>(std::lround(v));
}

// The activities of the run in legend order: the known ones first, then others as they come.
std::vector<std::string> activitiesOf(const StatusTimeline& timeline) {
  std::vector<std::string> found;
  for (const auto& unit : timeline.units)
    for (const auto& span : unit.spans)
      if (std::find(found.begin(), found.end(), span.activity) == found.end())
        found.push_back(span.activity);
  std::vector<std::string> ordered;
  for (const auto& name : knownActivities())
    if (std::find(found.begin(), found.end(), name) != found.end()) ordered.push_back(name);
  for (const auto& name : found)
    if (std::find(ordered.begin(), ordered.end(), name) == ordered.end()) ordered.push_back(name);
  return ordered;
}

std::vector<detail::LegendEntry> legendOf(const StatusTimeline& timeline) {
  std::vector<detail::LegendEntry> entries;
  for (const auto& activity : activitiesOf(timeline))
    entries.push_back({detail::LegendEntry::Kind::Swatch, activity, activityColor(activity)});
  if (!timeline.meetings.empty())
    entries.push_back(
        {detail::LegendEntry::Kind::Marker, "meeting", kMeetingMarkerColor, Marker::Disc});
  const bool lost = std::any_of(timeline.units.begin(), timeline.units.end(),
                                [](const UnitStatus& unit) { return unit.lostAt.has_value(); });
  if (lost)
    entries.push_back({detail::LegendEntry::Kind::Marker, "lost", kLostMarkerColor, Marker::Cross});
  return entries;
}

detail::Panel panelOf(const StatusTimelineFrame& frame) {
  detail::Panel panel{frame.left, frame.top, frame.right, frame.bottom, {}, {}};
  panel.x.lo = frame.timeLo;
  panel.x.hi = frame.timeHi;
  return panel;  // y has no ticks: rows, not values
}

void drawRows(RgbImage& image, const StatusTimeline& timeline, const StatusTimelineFrame& frame,
              int scale) {
  const double half = frame.barHalfHeight();
  for (size_t u = 0; u < timeline.units.size(); ++u) {
    const auto& unit = timeline.units[u];
    const double cy = frame.rowCenter(u);
    drawText(image, frame.left - 6 * scale, pixel(cy) - textHeight(scale) / 2 + scale, unit.name,
             detail::kPlotText, scale, TextAlign::Right);
    for (const auto& span : unit.spans) {
      const int x0 = pixel(frame.x(span.from));
      const int x1 = std::max(x0 + 1, pixel(frame.x(span.to)));
      fillRect(image, x0, pixel(cy - half), x1, pixel(cy + half), activityColor(span.activity));
    }
  }
}

// As in Fig. 12: a marker on both rows, joined by a thin line across the rows between them.
void drawMeetings(RgbImage& image, const StatusTimeline& timeline, const StatusTimelineFrame& frame,
                  int scale) {
  const double size = std::max(5.0, 0.9 * frame.barHalfHeight() + scale);
  for (const auto& meeting : timeline.meetings) {
    const int x = pixel(frame.x(meeting.time));
    fillRect(image, x, pixel(frame.rowCenter(meeting.a)), x + 1,
             pixel(frame.rowCenter(meeting.b)) + 1, kMeetingMarkerColor);
    for (const size_t unit : {meeting.a, meeting.b})
      drawMarker(image, x, frame.rowCenter(unit), Marker::Disc, size, kMeetingMarkerColor);
  }
}

void drawLosses(RgbImage& image, const StatusTimeline& timeline, const StatusTimelineFrame& frame,
                int scale) {
  const double size = std::max(7.0, 2.0 * frame.barHalfHeight() + 2 * scale);
  for (size_t u = 0; u < timeline.units.size(); ++u)
    if (timeline.units[u].lostAt)
      drawMarker(image, frame.x(*timeline.units[u].lostAt), frame.rowCenter(u), Marker::Cross, size,
                 kLostMarkerColor);
}

}  // namespace

double StatusTimelineFrame::x(double time) const {
  return panelOf(*this).px(time);
}

double StatusTimelineFrame::rowCenter(size_t unit) const {
  return top + (static_cast<double>(unit) + 0.5) * rowHeight;
}

double StatusTimelineFrame::barHalfHeight() const {
  return std::max(1.0, 0.5 * kBarFraction * rowHeight);
}

RgbImage renderStatusTimeline(const StatusTimeline& timeline, const std::string& title, int width,
                              int height, StatusTimelineFrame* frameOut) {
  RgbImage image(width, height, detail::kPlotBackground);
  const int s = labelScale(width, height);
  const int pad = 8 * s;
  drawText(image, width / 2, pad, title, detail::kPlotText, s, TextAlign::Center);

  const auto legend = legendOf(timeline);
  int nameWidth = 0;
  for (const auto& unit : timeline.units)
    nameWidth = std::max(nameWidth, textWidth(unit.name, s));
  StatusTimelineFrame frame;
  frame.left = pad + nameWidth + 6 * s + 4 * s;
  frame.top = pad + textHeight(s) + pad;
  const int right = legend.empty() ? width - pad - 3 * s * kGlyphAdvance
                                   : width - 2 * pad - detail::legendWidth(legend, s);
  frame.right = std::max(frame.left + 16, right);
  frame.bottom = std::max(frame.top + 16, height - (pad + 2 * textHeight(s) + 10 * s));
  frame.rowHeight = static_cast<double>(frame.bottom - frame.top) /
                    static_cast<double>(std::max<size_t>(1, timeline.units.size()));

  detail::Panel panel = panelOf(frame);
  panel.x = detail::niceAxis(0.0, timeline.endTime,
                             std::max(2, (frame.right - frame.left) / (70 * s)), false);
  frame.timeLo = panel.x.lo;
  frame.timeHi = panel.x.hi;
  detail::drawPanelAxes(image, panel, "", true, s);
  // Thin lines between the rows, as the value grid of the other plots.
  for (size_t u = 1; u < timeline.units.size(); ++u) {
    const int y = pixel(frame.top + static_cast<double>(u) * frame.rowHeight);
    fillRect(image, frame.left, y, frame.right, y + 1, detail::kPlotGrid);
  }
  drawRows(image, timeline, frame, s);
  drawMeetings(image, timeline, frame, s);
  drawLosses(image, timeline, frame, s);
  // The frame again: segments at 0 and at the end of the axis must not hide it.
  strokeRect(image, frame.left - 1, frame.top - 1, frame.right + 1, frame.bottom + 1,
             detail::kPlotFrame);
  drawText(image, (frame.left + frame.right) / 2, frame.bottom + 6 * s + textHeight(s) + 4 * s,
           "mission time (s)", detail::kPlotText, s, TextAlign::Center);

  if (!legend.empty())
    detail::drawLegendInFrame(image, frame.right + pad, frame.top, legend, s, frame);
  if (frameOut) *frameOut = frame;
  return image;
}

}  // namespace coinspect::eval
