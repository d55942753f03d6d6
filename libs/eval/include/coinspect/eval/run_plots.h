// 2D pictures of a recorded run, drawn with our own rasteriser (no GL): the score and detected
// points over mission time, and orthographic top (x-y) and side (x-z) views of the structure with
// the inspection boxes, the interest points coloured by their final ground-station score and each
// unit's trajectory (like Figure 10 of the CARIC paper). doc/evaluation.md shows them.
#pragma once

#include <cstddef>
#include <string>

#include "coinspect/eval/image.h"
#include "coinspect/eval/run_tracks.h"
#include "coinspect/world/scenario.h"

namespace coinspect::eval {

// The colour of the i-th unit of RunTracks::units, in every picture: distinct, and none of them
// on the red-yellow-green ramp of the point scores.
Rgb unitColor(size_t i);
// Colour of an interest point the ground station never scored.
inline constexpr Rgb kUnscoredColor{128, 128, 128};
// Colour of a unit after it was lost (3D pictures).
inline constexpr Rgb kLostUnitColor{70, 70, 70};
// Text scale (bitmap font) that suits a picture of this size: 1 below 600 px on the shorter
// side, 2 from 600 px, 3 from 900 px.
int labelScale(int width, int height);

// score.png: Q (upper panel) and detected points (lower panel) over mission time, events
// (start, end, deaths) as vertical dashed lines. `name` (the scenario) goes into the title.
RgbImage renderScorePlot(const RunTracks& tracks, const std::string& name, int width, int height);

enum class PlanAxis { Top, Side };  // Top: x right, y up. Side: x right, z up, seen from -y.

// Where a plan view put the world: pixel = (left + (u - u0) * scale, bottom - (v - v0) * scale)
// with (u, v) = (x, y) for Top and (x, z) for Side.
struct PlanFrame {
  PlanAxis axis = PlanAxis::Top;
  double u0 = 0.0, v0 = 0.0;  // world coordinates at the plot's bottom-left corner
  double scale = 1.0;         // pixels per metre
  int left = 0, bottom = 0;   // pixel of the plot's bottom-left corner
  int right = 0, top = 0;     // the plot area's other corner (pixels)
  // Pixel coordinates (x right, y down) of a world point.
  void toPixel(const world::Vec3& p, double& x, double& y) const;
};

// top.png / side.png. `frame`, when given, receives the mapping used (tests locate content).
RgbImage renderPlanView(const world::Scenario& scenario, const RunTracks& tracks, PlanAxis axis,
                        int width, int height, PlanFrame* frame = nullptr);

}  // namespace coinspect::eval
