// Drawing primitives on an RgbImage for plots: rectangles, thick lines, dashed lines, markers.
// All clip to the image; coordinates are pixels (x right, y down).
#pragma once

#include "coinspect/eval/image.h"

namespace coinspect::eval {

// Fills the pixels x0 <= x < x1, y0 <= y < y1.
void fillRect(RgbImage& image, int x0, int y0, int x1, int y1, Rgb color);
// Mixes the same pixels toward `color` by `amount` (0: unchanged, 1: filled): a veil that keeps
// text readable over a picture.
void veilRect(RgbImage& image, int x0, int y0, int x1, int y1, Rgb color, double amount);
// A one-pixel frame around the same pixels.
void strokeRect(RgbImage& image, int x0, int y0, int x1, int y1, Rgb color);
// A line `width` pixels wide with round ends.
void drawThickLine(RgbImage& image, double x0, double y0, double x1, double y1, double width,
                   Rgb color);
// A one-pixel line drawn `dash` pixels on, `gap` pixels off.
void drawDashedLine(RgbImage& image, double x0, double y0, double x1, double y1, int dash, int gap,
                    Rgb color);

// Point markers centred on (x, y), `size` pixels across.
enum class Marker { Disc, Ring, Square, Cross, Triangle };
void drawMarker(RgbImage& image, double x, double y, Marker marker, double size, Rgb color);

// `a` mixed with `b`: t = 0 gives a, t = 1 gives b.
Rgb mix(Rgb a, Rgb b, double t);

}  // namespace coinspect::eval
