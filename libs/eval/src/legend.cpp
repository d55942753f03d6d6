#include "legend.h"

#include <algorithm>

#include "coinspect/eval/bitmap_font.h"
#include "coinspect/eval/run_plots.h"

namespace coinspect::eval::detail {

namespace {

constexpr Rgb kWhite{255, 255, 255};
constexpr Rgb kText{35, 35, 35};
constexpr Rgb kFrame{110, 110, 110};

int rowHeight(int scale) {
  return textHeight(scale) + 5 * scale;
}

}  // namespace

std::vector<LegendEntry> unitEntries(const world::Scenario& scenario, const RunTracks& tracks) {
  std::vector<LegendEntry> entries;
  for (size_t i = 0; i < tracks.units.size(); ++i) {
    std::string label = tracks.units[i].name;
    for (const auto& spec : scenario.fleet)
      if (spec.name == label) label += std::string(" (") + world::toString(spec.role) + ")";
    entries.push_back({LegendEntry::Kind::Line, label, unitColor(i)});
  }
  return entries;
}

int legendWidth(const std::vector<LegendEntry>& entries, int scale) {
  int width = 0;
  for (const auto& entry : entries)
    width = std::max(width, textWidth(entry.label, scale));
  return width + 30 * scale;  // swatch, gaps and the frame
}

int legendHeight(const std::vector<LegendEntry>& entries, int scale) {
  return static_cast<int>(entries.size()) * rowHeight(scale) + 6 * scale;
}

void drawLegend(RgbImage& image, int left, int top, const std::vector<LegendEntry>& entries,
                int scale) {
  const int swatch = 14 * scale;
  const int width = legendWidth(entries, scale), height = legendHeight(entries, scale);
  fillRect(image, left, top, left + width, top + height, kWhite);
  strokeRect(image, left, top, left + width, top + height, kFrame);
  int y = top + 5 * scale;
  for (const auto& entry : entries) {
    const int x0 = left + 5 * scale;
    const int cx = x0 + swatch / 2, cy = y + kGlyphCapHeight * scale / 2;
    switch (entry.kind) {
      case LegendEntry::Kind::Line:
        drawThickLine(image, x0, cy, x0 + swatch, cy, 1.0 + scale, entry.color);
        break;
      case LegendEntry::Kind::Marker:
        drawMarker(image, cx, cy, entry.marker, 5.0 * scale + 2, entry.color);
        break;
      case LegendEntry::Kind::Box:
        strokeRect(image, x0, cy - 4 * scale, x0 + swatch, cy + 4 * scale, entry.color);
        break;
      case LegendEntry::Kind::ScoreBar:
        for (int x = 0; x < swatch; ++x)
          fillRect(image, x0 + x, cy - 3 * scale, x0 + x + 1, cy + 3 * scale,
                   scoreColor(static_cast<double>(x) / (swatch - 1)));
        break;
      case LegendEntry::Kind::Unscored:
        image.fillDisc(cx, cy, 2.5 * scale, entry.color);
        break;
      case LegendEntry::Kind::Swatch:
        fillRect(image, x0, cy - 4 * scale, x0 + swatch, cy + 4 * scale, entry.color);
        break;
    }
    drawText(image, x0 + swatch + 5 * scale, y, entry.label, kText, scale);
    y += rowHeight(scale);
  }
}

}  // namespace coinspect::eval::detail
