// A plain RGB raster and its PNG encoding: what every picture coinspect writes goes through.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace coinspect::eval {

struct Rgb {
  uint8_t r = 0, g = 0, b = 0;
  bool operator==(const Rgb& o) const { return r == o.r && g == o.g && b == o.b; }
};

class RgbImage {
 public:
  RgbImage(int width, int height, Rgb fill = {});

  int width() const { return width_; }
  int height() const { return height_; }
  Rgb& at(int x, int y) { return pixels_[static_cast<size_t>(y) * width_ + x]; }
  const Rgb& at(int x, int y) const { return pixels_[static_cast<size_t>(y) * width_ + x]; }
  bool inside(int x, int y) const { return x >= 0 && y >= 0 && x < width_ && y < height_; }
  // Draws a filled disc, clipped to the image.
  void fillDisc(double cx, double cy, double radius, Rgb color);
  // Draws a one-pixel line, clipped to the image.
  void drawLine(double x0, double y0, double x1, double y1, Rgb color);

 private:
  int width_, height_;
  std::vector<Rgb> pixels_;
};

// zlib level of the PNG data: the smallest files by default; replay frames, written by the
// thousand, take a faster level (about 5x faster at 960x540, files somewhat larger).
inline constexpr int kPngSmallest = 9;
inline constexpr int kPngFast = 1;

// 8-bit RGB PNG (zlib-compressed). Throws InputError naming the path when it cannot be written.
void writePng(const RgbImage& image, const std::filesystem::path& path,
              int compressionLevel = kPngSmallest);
// The encoded bytes (for tests and in-memory use).
std::vector<uint8_t> encodePng(const RgbImage& image, int compressionLevel = kPngSmallest);

// Colour ramp for a score in [0, 1]: dark red at 0, through orange and yellow, to green at 1.
Rgb scoreColor(double score);

}  // namespace coinspect::eval
