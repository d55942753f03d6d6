// Private to the pictures: the legend box shared by the plan views and the 3D overlays.
#pragma once

#include <string>
#include <vector>

#include "coinspect/eval/canvas.h"
#include "coinspect/eval/image.h"
#include "coinspect/eval/run_tracks.h"
#include "coinspect/world/scenario.h"

namespace coinspect::eval::detail {

struct LegendEntry {
  enum class Kind { Line, Marker, Box, ScoreBar, Unscored, Swatch } kind;  // Swatch: filled
  std::string label;
  Rgb color;
  Marker marker = Marker::Disc;
};

// One line entry per unit of `tracks`, in its unitColor: "name (role)" (the role from the
// scenario's fleet).
std::vector<LegendEntry> unitEntries(const world::Scenario& scenario, const RunTracks& tracks);

// Size of the legend box at this text scale.
int legendWidth(const std::vector<LegendEntry>& entries, int scale);
int legendHeight(const std::vector<LegendEntry>& entries, int scale);
// A white box with a frame, one entry per row: a swatch, then the label.
void drawLegend(RgbImage& image, int left, int top, const std::vector<LegendEntry>& entries,
                int scale);

// drawLegend with the top-left corner at (left, top), its box recorded in the frame's legendLeft,
// legendTop, legendRight and legendBottom (the pictures' frames, which tests locate content with).
template <class Frame>
void drawLegendInFrame(RgbImage& image, int left, int top, const std::vector<LegendEntry>& entries,
                       int scale, Frame& frame) {
  frame.legendLeft = left;
  frame.legendTop = top;
  frame.legendRight = left + legendWidth(entries, scale);
  frame.legendBottom = top + legendHeight(entries, scale);
  drawLegend(image, left, top, entries, scale);
}

}  // namespace coinspect::eval::detail
