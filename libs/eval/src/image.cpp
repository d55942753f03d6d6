#include "coinspect/eval/image.h"

#include <zlib.h>

#include <algorithm>
#include <cmath>
#include <fstream>

#include "coinspect/core/error.h"

namespace coinspect::eval {

RgbImage::RgbImage(int width, int height, Rgb fill)
    : width_(width), height_(height), pixels_(static_cast<size_t>(width) * height, fill) {
  COINSPECT_ASSERT(width > 0 && height > 0);
}

void RgbImage::fillDisc(double cx, double cy, double radius, Rgb color) {
  const int x0 = static_cast<int>(std::floor(cx - radius)),
            x1 = static_cast<int>(std::ceil(cx + radius));
  const int y0 = static_cast<int>(std::floor(cy - radius)),
            y1 = static_cast<int>(std::ceil(cy + radius));
  for (int y = std::max(y0, 0); y <= std::min(y1, height_ - 1); ++y)
    for (int x = std::max(x0, 0); x <= std::min(x1, width_ - 1); ++x)
      if ((x + 0.5 - cx) * (x + 0.5 - cx) + (y + 0.5 - cy) * (y + 0.5 - cy) <= radius * radius)
        at(x, y) = color;
}

void RgbImage::drawLine(double x0, double y0, double x1, double y1, Rgb color) {
  const double steps = std::ceil(std::max(std::abs(x1 - x0), std::abs(y1 - y0)));
  if (!std::isfinite(steps) || steps > 1e5) return;  // off-screen projections: nothing to draw
  for (int i = 0; i <= static_cast<int>(steps); ++i) {
    const double t = steps > 0 ? i / steps : 0.0;
    const int x = static_cast<int>(std::floor(x0 + t * (x1 - x0)));
    const int y = static_cast<int>(std::floor(y0 + t * (y1 - y0)));
    if (inside(x, y)) at(x, y) = color;
  }
}

namespace {

void putBigEndian32(std::vector<uint8_t>& out, uint32_t value) {
  for (int shift = 24; shift >= 0; shift -= 8)
    out.push_back(static_cast<uint8_t>(value >> shift));
}

void putChunk(std::vector<uint8_t>& out, const char type[4], const std::vector<uint8_t>& data) {
  putBigEndian32(out, static_cast<uint32_t>(data.size()));
  const size_t typeStart = out.size();
  out.insert(out.end(), type, type + 4);
  out.insert(out.end(), data.begin(), data.end());
  // The CRC covers the chunk type and data.
  const uLong crc = crc32(0L, out.data() + typeStart, static_cast<uInt>(out.size() - typeStart));
  putBigEndian32(out, static_cast<uint32_t>(crc));
}

}  // namespace

std::vector<uint8_t> encodePng(const RgbImage& image, int compressionLevel) {
  // Each scanline is prefixed by its filter type (0: none).
  std::vector<uint8_t> raw;
  raw.reserve(static_cast<size_t>(image.height()) * (1 + 3 * image.width()));
  for (int y = 0; y < image.height(); ++y) {
    raw.push_back(0);
    for (int x = 0; x < image.width(); ++x) {
      const Rgb& p = image.at(x, y);
      raw.insert(raw.end(), {p.r, p.g, p.b});
    }
  }
  uLongf compressedSize = compressBound(static_cast<uLong>(raw.size()));
  std::vector<uint8_t> compressed(compressedSize);
  const int status = compress2(compressed.data(), &compressedSize, raw.data(),
                               static_cast<uLong>(raw.size()), compressionLevel);
  COINSPECT_ASSERT(status == Z_OK);
  compressed.resize(compressedSize);

  std::vector<uint8_t> png = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
  std::vector<uint8_t> header;
  putBigEndian32(header, static_cast<uint32_t>(image.width()));
  putBigEndian32(header, static_cast<uint32_t>(image.height()));
  header.insert(header.end(), {8, 2, 0, 0, 0});  // 8-bit depth, truecolour, no interlace
  putChunk(png, "IHDR", header);
  putChunk(png, "IDAT", compressed);
  putChunk(png, "IEND", {});
  return png;
}

void writePng(const RgbImage& image, const std::filesystem::path& path, int compressionLevel) {
  const auto bytes = encodePng(image, compressionLevel);
  std::ofstream out(path, std::ios::binary);
  out.write(reinterpret_cast<const char*>(bytes.data()),
            static_cast<std::streamsize>(bytes.size()));
  if (!out) throw InputError(path.string(), "", "cannot write PNG image");
}

Rgb scoreColor(double score) {
  score = std::clamp(score, 0.0, 1.0);
  // Piecewise-linear: 0 dark red (150,20,20), 0.5 yellow (240,200,30), 1 green (30,170,60).
  const auto mix = [](double a, double b, double t) {
    return static_cast<uint8_t>(std::lround(a + (b - a) * t));
  };
  if (score < 0.5) {
    const double t = score / 0.5;
    return {mix(150, 240, t), mix(20, 200, t), mix(20, 30, t)};
  }
  const double t = (score - 0.5) / 0.5;
  return {mix(240, 30, t), mix(200, 170, t), mix(30, 60, t)};
}

}  // namespace coinspect::eval
