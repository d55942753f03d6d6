#include "coinspect/eval/canvas.h"

#include <algorithm>
#include <cmath>

namespace coinspect::eval {

void fillRect(RgbImage& image, int x0, int y0, int x1, int y1, Rgb color) {
  for (int y = std::max(y0, 0); y < std::min(y1, image.height()); ++y)
    for (int x = std::max(x0, 0); x < std::min(x1, image.width()); ++x)
      image.at(x, y) = color;
}

void veilRect(RgbImage& image, int x0, int y0, int x1, int y1, Rgb color, double amount) {
  for (int y = std::max(y0, 0); y < std::min(y1, image.height()); ++y)
    for (int x = std::max(x0, 0); x < std::min(x1, image.width()); ++x)
      image.at(x, y) = mix(image.at(x, y), color, amount);
}

void strokeRect(RgbImage& image, int x0, int y0, int x1, int y1, Rgb color) {
  fillRect(image, x0, y0, x1, y0 + 1, color);
  fillRect(image, x0, y1 - 1, x1, y1, color);
  fillRect(image, x0, y0, x0 + 1, y1, color);
  fillRect(image, x1 - 1, y0, x1, y1, color);
}

void drawThickLine(RgbImage& image, double x0, double y0, double x1, double y1, double width,
                   Rgb color) {
  if (width <= 1.0) {
    image.drawLine(x0, y0, x1, y1, color);
    return;
  }
  const double length = std::hypot(x1 - x0, y1 - y0);
  if (!std::isfinite(length) || length > 1e5) return;  // far off-screen: nothing to draw
  // A disc every half pixel along the line: round ends and joins, no gaps.
  const int steps = static_cast<int>(std::ceil(2.0 * length));
  for (int i = 0; i <= steps; ++i) {
    const double t = steps > 0 ? static_cast<double>(i) / steps : 0.0;
    image.fillDisc(x0 + t * (x1 - x0), y0 + t * (y1 - y0), 0.5 * width, color);
  }
}

void drawDashedLine(RgbImage& image, double x0, double y0, double x1, double y1, int dash, int gap,
                    Rgb color) {
  const double length = std::hypot(x1 - x0, y1 - y0);
  if (!std::isfinite(length) || length > 1e5 || dash <= 0) return;
  const int steps = static_cast<int>(std::ceil(length));
  for (int i = 0; i <= steps; ++i) {
    if (i % (dash + std::max(gap, 0)) >= dash) continue;
    const double t = steps > 0 ? static_cast<double>(i) / steps : 0.0;
    const int x = static_cast<int>(std::floor(x0 + t * (x1 - x0)));
    const int y = static_cast<int>(std::floor(y0 + t * (y1 - y0)));
    if (image.inside(x, y)) image.at(x, y) = color;
  }
}

void drawMarker(RgbImage& image, double x, double y, Marker marker, double size, Rgb color) {
  const double r = 0.5 * size;
  const double stroke = std::max(1.5, size / 5.0);
  switch (marker) {
    case Marker::Disc:
      image.fillDisc(x, y, r, color);
      break;
    case Marker::Ring:
      // A white-filled ring: stands out on lines of the same colour.
      image.fillDisc(x, y, r, color);
      image.fillDisc(x, y, std::max(0.0, r - stroke), Rgb{255, 255, 255});
      break;
    case Marker::Square: {
      const int x0 = static_cast<int>(std::lround(x - r)),
                y0 = static_cast<int>(std::lround(y - r));
      const int side = static_cast<int>(std::lround(size));
      fillRect(image, x0, y0, x0 + side, y0 + side, color);
      break;
    }
    case Marker::Cross:
      drawThickLine(image, x - r, y - r, x + r, y + r, stroke, color);
      drawThickLine(image, x - r, y + r, x + r, y - r, stroke, color);
      break;
    case Marker::Triangle:
      // Pointing up, filled row by row.
      for (int row = 0; row <= static_cast<int>(std::ceil(size)); ++row) {
        const double half = 0.5 * row * 1.15;
        const int py = static_cast<int>(std::lround(y - r + row));
        fillRect(image, static_cast<int>(std::lround(x - half)), py,
                 static_cast<int>(std::lround(x + half)) + 1, py + 1, color);
      }
      break;
  }
}

Rgb mix(Rgb a, Rgb b, double t) {
  t = std::clamp(t, 0.0, 1.0);
  const auto channel = [t](uint8_t u, uint8_t v) {
    return static_cast<uint8_t>(std::lround(u + (v - u) * t));
  };
  return {channel(a.r, b.r), channel(a.g, b.g), channel(a.b, b.b)};
}

}  // namespace coinspect::eval
