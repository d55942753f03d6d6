// top.png and side.png: orthographic views of the structure, boxes, scored points and
// trajectories, with axes in metres and a legend.
#include <algorithm>
#include <cinttypes>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numeric>

#include "coinspect/eval/bitmap_font.h"
#include "coinspect/eval/canvas.h"
#include "coinspect/eval/run_plots.h"
#include "coinspect/record/observations.h"
#include "legend.h"
#include "plot_axes.h"

namespace coinspect::eval {

namespace {

using world::Vec3;

constexpr Rgb kWhite{255, 255, 255};
constexpr Rgb kText{35, 35, 35};
constexpr Rgb kFrame{110, 110, 110};
constexpr Rgb kGrid{236, 236, 236};
constexpr Rgb kFar{232, 232, 232};   // structure far from the viewer (low, or at the back)
constexpr Rgb kNear{172, 172, 172};  // structure near the viewer (high, or at the front)
constexpr Rgb kBoxColor{40, 110, 220};
constexpr Rgb kGroundLine{150, 120, 90};
constexpr Rgb kBelowGround{244, 240, 232};
constexpr Rgb kDeathColor{20, 20, 20};
constexpr Rgb kMeetingColor{0, 0, 0};  // a meeting of two units (feature missions)
constexpr Rgb kPointOutline{45, 45, 45};

// (u, v) plane coordinates and the depth toward the viewer (larger = nearer).
struct Projected {
  double u, v, depth;
};

Projected project(PlanAxis axis, const Vec3& p) {
  return axis == PlanAxis::Top ? Projected{p.x(), p.y(), p.z()} : Projected{p.x(), p.z(), -p.y()};
}

Vec3 towardViewer(PlanAxis axis) {
  return axis == PlanAxis::Top ? Vec3(0, 0, 1) : Vec3(0, -1, 0);
}

// Filled triangles with a depth buffer, shaded from kFar to kNear by depth; triangles seen
// edge-on (walls in the top view) are drawn as depth-tested lines, else thin parts vanish.
class StructureRaster {
 public:
  StructureRaster(RgbImage& image, const PlanFrame& frame, double depthLo, double depthHi)
      : image_(image),
        frame_(frame),
        depthLo_(depthLo),
        depthHi_(std::max(depthHi, depthLo + 1e-6)),
        depth_(static_cast<size_t>(image.width()) * image.height(),
               -std::numeric_limits<double>::infinity()) {}

  void triangle(const Vec3& a, const Vec3& b, const Vec3& c) {
    const Vec3 normal = (b - a).cross(c - a);
    const double area = normal.norm();
    if (!(area > 0.0)) return;
    const double facing = std::abs(normal.dot(towardViewer(frame_.axis))) / area;
    const double light = 0.86 + 0.14 * facing;  // slopes a little darker than flat faces
    std::array<Pixel, 3> p = {pixelOf(a), pixelOf(b), pixelOf(c)};
    if (facing < 0.2) {
      line(p[0], p[1], light);
      line(p[1], p[2], light);
      line(p[2], p[0], light);
      return;
    }
    const double area2 =
        (p[1].x - p[0].x) * (p[2].y - p[0].y) - (p[2].x - p[0].x) * (p[1].y - p[0].y);
    if (std::abs(area2) < 1e-12) return;
    const int x0 =
        std::max(frame_.left, static_cast<int>(std::floor(std::min({p[0].x, p[1].x, p[2].x}))));
    const int x1 =
        std::min(frame_.right - 1, static_cast<int>(std::ceil(std::max({p[0].x, p[1].x, p[2].x}))));
    const int y0 =
        std::max(frame_.top, static_cast<int>(std::floor(std::min({p[0].y, p[1].y, p[2].y}))));
    const int y1 = std::min(frame_.bottom - 1,
                            static_cast<int>(std::ceil(std::max({p[0].y, p[1].y, p[2].y}))));
    for (int y = y0; y <= y1; ++y)
      for (int x = x0; x <= x1; ++x) {
        const double cx = x + 0.5, cy = y + 0.5;
        const double w0 = edge(p[1], p[2], cx, cy) / area2;
        const double w1 = edge(p[2], p[0], cx, cy) / area2;
        const double w2 = 1.0 - w0 - w1;
        if (w0 < 0 || w1 < 0 || w2 < 0) continue;
        plot(x, y, w0 * p[0].depth + w1 * p[1].depth + w2 * p[2].depth, light);
      }
  }

 private:
  struct Pixel {
    double x, y, depth;
  };
  Pixel pixelOf(const Vec3& p) const {
    Pixel out;
    frame_.toPixel(p, out.x, out.y);
    out.depth = project(frame_.axis, p).depth;
    return out;
  }
  static double edge(const Pixel& a, const Pixel& b, double x, double y) {
    return (b.x - a.x) * (y - a.y) - (x - a.x) * (b.y - a.y);
  }
  void line(const Pixel& a, const Pixel& b, double light) {
    const int steps =
        static_cast<int>(std::ceil(std::max(std::abs(b.x - a.x), std::abs(b.y - a.y))));
    if (steps > 100000) return;
    for (int i = 0; i <= steps; ++i) {
      const double t = steps > 0 ? static_cast<double>(i) / steps : 0.0;
      plot(static_cast<int>(std::floor(a.x + t * (b.x - a.x))),
           static_cast<int>(std::floor(a.y + t * (b.y - a.y))), a.depth + t * (b.depth - a.depth),
           light);
    }
  }
  void plot(int x, int y, double depth, double light) {
    if (x < frame_.left || x >= frame_.right || y < frame_.top || y >= frame_.bottom) return;
    double& stored = depth_[static_cast<size_t>(y) * image_.width() + x];
    if (depth <= stored) return;
    stored = depth;
    const Rgb base = mix(kFar, kNear, (depth - depthLo_) / (depthHi_ - depthLo_));
    image_.at(x, y) = mix(Rgb{0, 0, 0}, base, light);
  }

  RgbImage& image_;
  const PlanFrame& frame_;
  double depthLo_, depthHi_;
  std::vector<double> depth_;
};

struct Extent {
  double uMin = std::numeric_limits<double>::infinity(), uMax = -uMin;
  double vMin = uMin, vMax = -uMin;
  double dMin = uMin, dMax = -uMin;  // depth of the structure
  void add(const Projected& p) {
    uMin = std::min(uMin, p.u), uMax = std::max(uMax, p.u);
    vMin = std::min(vMin, p.v), vMax = std::max(vMax, p.v);
  }
};

Extent extentOf(const world::Scenario& scenario, const RunTracks& tracks, PlanAxis axis) {
  Extent extent;
  for (const auto& mesh : scenario.meshes)
    for (const auto& vertex : mesh.vertices) {
      const Projected p = project(axis, vertex.cast<double>());
      extent.add(p);
      extent.dMin = std::min(extent.dMin, p.depth), extent.dMax = std::max(extent.dMax, p.depth);
    }
  for (const auto& box : scenario.boxes)
    for (const auto& corner : box.vertices())
      extent.add(project(axis, corner));
  for (const auto& point : scenario.interestPoints.points())
    extent.add(project(axis, point.position));
  for (const auto& unit : tracks.units)
    for (const auto& sample : unit.poses)
      extent.add(project(axis, sample.position));
  if (axis == PlanAxis::Side) extent.add({extent.uMin, scenario.groundZ, 0.0});
  if (!std::isfinite(extent.uMin)) extent = Extent{-1, 1, -1, 1, 0, 1};
  return extent;
}

}  // namespace

void PlanFrame::toPixel(const Vec3& p, double& x, double& y) const {
  const Projected q = project(axis, p);
  x = left + (q.u - u0) * scale;
  y = bottom - (q.v - v0) * scale;
}

RgbImage renderPlanView(const world::Scenario& scenario, const RunTracks& tracks, PlanAxis axis,
                        int width, int height, PlanFrame* frameOut) {
  RgbImage image(width, height, kWhite);
  const int s = labelScale(width, height);
  const int pad = 8 * s;
  const bool top = axis == PlanAxis::Top;

  // Legend first: it decides how much width the plot gets.
  auto legend = detail::unitEntries(scenario, tracks);
  bool anyDeath = false;
  for (const auto& unit : tracks.units)
    anyDeath = anyDeath || unit.deathTime.has_value();
  legend.push_back({detail::LegendEntry::Kind::Marker, "start", kText, Marker::Ring});
  legend.push_back({detail::LegendEntry::Kind::Marker, "end", kText, Marker::Square});
  if (anyDeath)
    legend.push_back({detail::LegendEntry::Kind::Marker, "lost", kDeathColor, Marker::Cross});
  // Meetings (feature missions: two units linked again after a gap), where data changed hands.
  std::vector<Vec3> meetings;
  for (const auto& event : tracks.events) {
    if (event.kind != record::MissionEventKind::Meeting) continue;
    const int a = tracks.unitIndex(event.unit), b = tracks.unitIndex(event.detail);
    if (a < 0 || b < 0 || tracks.units[a].poses.empty() || tracks.units[b].poses.empty()) continue;
    meetings.push_back(0.5 * (poseAt(tracks.units[a], event.time).position +
                              poseAt(tracks.units[b], event.time).position));
  }
  if (!meetings.empty())
    legend.push_back(
        {detail::LegendEntry::Kind::Marker, "meeting", kMeetingColor, Marker::Triangle});
  legend.push_back({detail::LegendEntry::Kind::Box, "inspection box", kBoxColor});
  legend.push_back({detail::LegendEntry::Kind::ScoreBar, "point score 0..1", kText});
  legend.push_back({detail::LegendEntry::Kind::Unscored, "not scored", kUnscoredColor});
  const int legendW = detail::legendWidth(legend, s);

  const Extent extent = extentOf(scenario, tracks, axis);
  const double margin =
      0.04 * std::max({extent.uMax - extent.uMin, extent.vMax - extent.vMin, 1.0});
  // Tick labels of the vertical axis decide the left margin; estimate them from the data range.
  const auto vGuess = detail::niceAxis(extent.vMin - margin, extent.vMax + margin, 8, false);
  int labelWidth = 0;
  for (double v : vGuess.ticks)
    labelWidth = std::max(labelWidth, textWidth(detail::tickLabel(v, vGuess.decimals), s));
  labelWidth = std::max(labelWidth, textWidth("-000", s));

  PlanFrame frame;
  frame.axis = axis;
  frame.left = 4 * s + textHeight(s) + pad + labelWidth + 7 * s;
  frame.top = pad + textHeight(s) + pad;
  frame.right = std::max(frame.left + 16, width - 2 * pad - legendW);
  frame.bottom = std::max(frame.top + 16, height - (pad + 2 * textHeight(s) + 10 * s));
  // Equal scale on both axes; the range of the roomier axis grows to fill the plot.
  const double uSpan = extent.uMax - extent.uMin + 2 * margin;
  const double vSpan = extent.vMax - extent.vMin + 2 * margin;
  frame.scale = std::min((frame.right - frame.left) / uSpan, (frame.bottom - frame.top) / vSpan);
  frame.u0 = 0.5 * (extent.uMin + extent.uMax) - 0.5 * (frame.right - frame.left) / frame.scale;
  frame.v0 = 0.5 * (extent.vMin + extent.vMax) - 0.5 * (frame.bottom - frame.top) / frame.scale;
  if (frameOut) *frameOut = frame;
  const auto pixelX = [&](double u) { return frame.left + (u - frame.u0) * frame.scale; };
  const auto pixelY = [&](double v) { return frame.bottom - (v - frame.v0) * frame.scale; };
  const auto pixel = [&](const Vec3& p, double& x, double& y) { frame.toPixel(p, x, y); };

  // Grid and, in the side view, the ground.
  const auto uAxis = detail::niceAxis(frame.u0, frame.u0 + (frame.right - frame.left) / frame.scale,
                                      std::max(2, (frame.right - frame.left) / (70 * s)), false);
  const auto vAxis = detail::niceAxis(frame.v0, frame.v0 + (frame.bottom - frame.top) / frame.scale,
                                      std::max(2, (frame.bottom - frame.top) / (55 * s)), false);
  if (!top) {
    const int ground = static_cast<int>(std::lround(pixelY(scenario.groundZ)));
    fillRect(image, frame.left, std::max(ground, frame.top), frame.right, frame.bottom,
             kBelowGround);
  }
  for (double u : uAxis.ticks) {
    const int x = static_cast<int>(std::lround(pixelX(u)));
    fillRect(image, x, frame.top, x + 1, frame.bottom, kGrid);
  }
  for (double v : vAxis.ticks) {
    const int y = static_cast<int>(std::lround(pixelY(v)));
    fillRect(image, frame.left, y, frame.right, y + 1, kGrid);
  }
  if (!top) {
    const int ground = static_cast<int>(std::lround(pixelY(scenario.groundZ)));
    if (ground >= frame.top && ground < frame.bottom)
      fillRect(image, frame.left, ground, frame.right, ground + s, kGroundLine);
  }

  // Structure.
  StructureRaster raster(image, frame, extent.dMin, extent.dMax);
  for (const auto& mesh : scenario.meshes)
    for (const auto& t : mesh.triangles)
      raster.triangle(mesh.vertex(t[0]), mesh.vertex(t[1]), mesh.vertex(t[2]));

  // Boxes: the 12 edges of each, in the reference's vertex order.
  static constexpr int kEdges[12][2] = {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {4, 5}, {5, 6},
                                        {6, 7}, {7, 4}, {0, 4}, {1, 5}, {2, 6}, {3, 7}};
  for (const auto& box : scenario.boxes) {
    const auto corners = box.vertices();
    for (const auto& e : kEdges) {
      double x0, y0, x1, y1;
      pixel(corners[e[0]], x0, y0);
      pixel(corners[e[1]], x1, y1);
      drawThickLine(image, x0, y0, x1, y1, s, kBoxColor);
    }
  }

  // Interest points: the unscored ones first, then the scored ones (coverage is what the view
  // is for), each group farthest first so that the points facing the viewer stay on top.
  const auto& points = scenario.interestPoints.points();
  const auto valueOf = [&](const world::InterestPoint& point) {
    return point.index < tracks.finalValues.size() ? tracks.finalValues[point.index] : 0.0;
  };
  std::vector<size_t> order(points.size());
  std::iota(order.begin(), order.end(), size_t{0});
  std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) {
    const bool scoredA = valueOf(points[a]) > 0.0, scoredB = valueOf(points[b]) > 0.0;
    if (scoredA != scoredB) return scoredB;
    return project(axis, points[a].position).depth < project(axis, points[b].position).depth;
  });
  // Few points get big discs with a dark outline (readable on the structure's greys); tens of
  // thousands get small plain dots that leave the structure visible.
  const double pointRadius = (points.size() > 5000  ? 1.2
                              : points.size() > 500 ? 2.0
                                                    : 3.0) *
                             (0.5 + 0.5 * s);
  const bool outline = points.size() <= 5000;
  for (size_t i : order) {
    const auto& point = points[i];
    const double value = valueOf(point);
    double x, y;
    pixel(point.position, x, y);
    if (outline) image.fillDisc(x, y, pointRadius + 1.0, kPointOutline);
    image.fillDisc(x, y, pointRadius, value > 0.0 ? scoreColor(value) : kUnscoredColor);
  }

  // Trajectories (samples closer than half a pixel to the last drawn one are skipped), then
  // their start, end and loss markers above every line.
  const double lineWidth = 1.0 + s;
  for (size_t i = 0; i < tracks.units.size(); ++i) {
    const auto& poses = tracks.units[i].poses;
    if (poses.empty()) continue;
    double lastX, lastY;
    pixel(poses.front().position, lastX, lastY);
    for (const auto& sample : poses) {
      double x, y;
      pixel(sample.position, x, y);
      if (std::hypot(x - lastX, y - lastY) < 0.5) continue;
      drawThickLine(image, lastX, lastY, x, y, lineWidth, unitColor(i));
      lastX = x, lastY = y;
    }
  }
  const double markerSize = 5.0 * s + 4.0;
  for (size_t i = 0; i < tracks.units.size(); ++i) {
    const auto& unit = tracks.units[i];
    if (unit.poses.empty()) continue;
    double x, y;
    pixel(unit.poses.front().position, x, y);
    drawMarker(image, x, y, Marker::Ring, markerSize, unitColor(i));
    pixel(unit.poses.back().position, x, y);
    drawMarker(image, x, y, Marker::Square, markerSize, unitColor(i));
    if (unit.deathTime) {
      pixel(poseAt(unit, *unit.deathTime).position, x, y);
      drawMarker(image, x, y, Marker::Cross, markerSize + 2.0 * s, kDeathColor);
    }
  }
  for (const Vec3& place : meetings) {
    double x, y;
    pixel(place, x, y);
    drawMarker(image, x, y, Marker::Triangle, markerSize, kMeetingColor);
  }

  // Frame, ticks, labels, title, legend: drawn last, over anything that crossed the border.
  fillRect(image, 0, 0, frame.left - 1, height, kWhite);
  fillRect(image, frame.right + 1, 0, width, height, kWhite);
  fillRect(image, 0, 0, width, frame.top - 1, kWhite);
  fillRect(image, 0, frame.bottom + 1, width, height, kWhite);
  strokeRect(image, frame.left - 1, frame.top - 1, frame.right + 1, frame.bottom + 1, kFrame);
  const int tick = 4 * s;
  for (double u : uAxis.ticks) {
    const int x = static_cast<int>(std::lround(pixelX(u)));
    fillRect(image, x, frame.bottom, x + 1, frame.bottom + tick, kFrame);
    drawText(image, x, frame.bottom + tick + 2 * s, detail::tickLabel(u, uAxis.decimals), kText, s,
             TextAlign::Center);
  }
  for (double v : vAxis.ticks) {
    const int y = static_cast<int>(std::lround(pixelY(v)));
    fillRect(image, frame.left - tick, y, frame.left, y + 1, kFrame);
    drawText(image, frame.left - tick - 3 * s, y - textHeight(s) / 2 + s,
             detail::tickLabel(v, vAxis.decimals), kText, s, TextAlign::Right);
  }
  drawText(image, (frame.left + frame.right) / 2,
           frame.bottom + tick + 4 * s + textHeight(s) + 4 * s, "x (m)", kText, s,
           TextAlign::Center);
  drawTextUpward(image, 4 * s, (frame.top + frame.bottom) / 2, top ? "y (m)" : "z (m)", kText, s,
                 TextAlign::Center);
  char title[256];
  std::snprintf(title, sizeof(title), "%s, %s: Q = %.2f, detected %" PRIu64 " / %zu points",
                scenario.name.c_str(), top ? "top view (x-y)" : "side view (x-z, from -y)",
                tracks.finalScore(), tracks.finalDetected(), points.size());
  drawText(image, (frame.left + frame.right) / 2, pad, title, kText, s, TextAlign::Center);
  detail::drawLegend(image, frame.right + pad, frame.top, legend, s);
  return image;
}

}  // namespace coinspect::eval
