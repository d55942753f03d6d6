#include "plot_panel.h"

#include <cmath>

#include "coinspect/eval/bitmap_font.h"
#include "coinspect/eval/canvas.h"

namespace coinspect::eval::detail {

void drawPanelAxes(RgbImage& image, const Panel& panel, const std::string& yTitle, bool xLabels,
                   int scale) {
  const int tick = 4 * scale;
  for (double v : panel.y.ticks) {
    const int y = static_cast<int>(std::lround(panel.py(v)));
    fillRect(image, panel.left, y, panel.right, y + 1, kPlotGrid);
    fillRect(image, panel.left - tick, y, panel.left, y + 1, kPlotFrame);
    drawText(image, panel.left - tick - 3 * scale, y - textHeight(scale) / 2 + scale,
             tickLabel(v, panel.y.decimals), kPlotText, scale, TextAlign::Right);
  }
  for (double t : panel.x.ticks) {
    const int x = static_cast<int>(std::lround(panel.px(t)));
    fillRect(image, x, panel.top, x + 1, panel.bottom, kPlotGrid);
    fillRect(image, x, panel.bottom, x + 1, panel.bottom + tick, kPlotFrame);
    if (xLabels)
      drawText(image, x, panel.bottom + tick + 2 * scale, tickLabel(t, panel.x.decimals), kPlotText,
               scale, TextAlign::Center);
  }
  strokeRect(image, panel.left - 1, panel.top - 1, panel.right + 1, panel.bottom + 1, kPlotFrame);
  drawTextUpward(image, 4 * scale, (panel.top + panel.bottom) / 2, yTitle, kPlotText, scale,
                 TextAlign::Center);
}

void drawSteps(RgbImage& image, const Panel& panel,
               const std::vector<std::pair<double, double>>& steps, double endTime, Rgb color,
               int scale, bool fillBelow) {
  std::vector<std::pair<double, double>> corners = {{panel.x.lo, 0.0}};
  for (const auto& [t, v] : steps) {
    corners.emplace_back(t, corners.back().second);
    corners.emplace_back(t, v);
  }
  corners.emplace_back(endTime, corners.back().second);
  if (fillBelow) {
    const Rgb fill = mix(color, kPlotBackground, 0.82);
    for (size_t i = 1; i < corners.size(); ++i) {
      const auto& [t0, v0] = corners[i - 1];
      const auto& [t1, v1] = corners[i];
      if (v0 != v1) continue;  // only horizontal runs enclose an area
      const int x0 = static_cast<int>(std::lround(panel.px(t0)));
      const int x1 = static_cast<int>(std::lround(panel.px(t1)));
      fillRect(image, x0, static_cast<int>(std::lround(panel.py(v0))), x1 + 1, panel.bottom, fill);
    }
  }
  for (size_t i = 1; i < corners.size(); ++i)
    drawThickLine(image, panel.px(corners[i - 1].first), panel.py(corners[i - 1].second),
                  panel.px(corners[i].first), panel.py(corners[i].second), 1.0 + scale, color);
}

}  // namespace coinspect::eval::detail
