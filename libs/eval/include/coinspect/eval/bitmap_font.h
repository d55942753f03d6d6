// A small bitmap font of our own for the labels of the pictures (axis numbers, titles, legends):
// printable ASCII, each glyph 5 x 7 pixels above the baseline plus 2 rows of descender, drawn
// at an integer scale. No font files, no FreeType: every machine draws the same pixels.
#pragma once

#include <string>

#include "coinspect/eval/image.h"

namespace coinspect::eval {

// Cell metrics at scale 1, in pixels.
inline constexpr int kGlyphWidth = 5;
inline constexpr int kGlyphAdvance = 6;    // glyph + one column of spacing
inline constexpr int kGlyphCapHeight = 7;  // rows above the baseline
inline constexpr int kGlyphHeight = 9;     // with the descender (g, j, p, q, y, comma)

// Width and height of `text` drawn at `scale` (one line; no trailing spacing column).
int textWidth(const std::string& text, int scale = 1);
inline int textHeight(int scale = 1) {
  return kGlyphHeight * scale;
}

enum class TextAlign { Left, Center, Right };

// Draws one line of text whose top-left corner (or top-centre, top-right) is at (x, y).
// Characters outside printable ASCII are drawn as '?'. Clipped to the image.
void drawText(RgbImage& image, int x, int y, const std::string& text, Rgb color, int scale = 1,
              TextAlign align = TextAlign::Left);

// Draws text rotated a quarter turn counter-clockwise (reading upward), e.g. a y-axis label.
// x is the left edge of the rotated text (where the tops of the glyphs are); y is where the text
// starts (its lowest pixel row) for Left, its middle for Center, where it ends for Right.
void drawTextUpward(RgbImage& image, int x, int y, const std::string& text, Rgb color,
                    int scale = 1, TextAlign align = TextAlign::Left);

}  // namespace coinspect::eval
