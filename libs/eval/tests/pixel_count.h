// Pixel counts the picture tests locate content with.
#pragma once

#include "coinspect/eval/image.h"

namespace coinspect::eval::test {

// Pixels of `color` within `radius` pixels of (x, y).
inline int countNear(const RgbImage& image, double x, double y, int radius, Rgb color) {
  int count = 0;
  for (int py = static_cast<int>(y) - radius; py <= static_cast<int>(y) + radius; ++py)
    for (int px = static_cast<int>(x) - radius; px <= static_cast<int>(x) + radius; ++px)
      if (image.inside(px, py) && image.at(px, py) == color) ++count;
  return count;
}

// Pixels of `color` with x0 <= x < x1 and y0 <= y < y1 (clipped to the image).
inline int countIn(const RgbImage& image, int x0, int y0, int x1, int y1, Rgb color) {
  int count = 0;
  for (int y = y0; y < y1; ++y)
    for (int x = x0; x < x1; ++x)
      if (image.inside(x, y) && image.at(x, y) == color) ++count;
  return count;
}

}  // namespace coinspect::eval::test
