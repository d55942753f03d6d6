#include "coinspect/eval/image.h"

#include <gtest/gtest.h>
#include <zlib.h>

#include "coinspect/testing/paths.h"

namespace coinspect::eval {

namespace {
uint32_t bigEndian32(const std::vector<uint8_t>& bytes, size_t at) {
  return uint32_t(bytes[at]) << 24 | uint32_t(bytes[at + 1]) << 16 | uint32_t(bytes[at + 2]) << 8 |
         bytes[at + 3];
}
}  // namespace

TEST(Png, EncodesSignatureHeaderAndPixelsThatDecodeBack) {
  RgbImage image(3, 2, {10, 20, 30});
  image.at(2, 1) = {255, 0, 128};
  const auto png = encodePng(image);
  const std::vector<uint8_t> signature = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
  ASSERT_GT(png.size(), 8u + 25u);
  EXPECT_TRUE(std::equal(signature.begin(), signature.end(), png.begin()));
  // IHDR: length 13, then width 3, height 2, depth 8, colour type 2.
  EXPECT_EQ(bigEndian32(png, 8), 13u);
  EXPECT_EQ(std::string(png.begin() + 12, png.begin() + 16), "IHDR");
  EXPECT_EQ(bigEndian32(png, 16), 3u);
  EXPECT_EQ(bigEndian32(png, 20), 2u);
  EXPECT_EQ(png[24], 8);
  EXPECT_EQ(png[25], 2);
  // The IHDR CRC covers type and data.
  EXPECT_EQ(bigEndian32(png, 29), crc32(0, png.data() + 12, 17));
  // IDAT follows: inflate it and compare with the filter-0 scanlines.
  const uint32_t idatLength = bigEndian32(png, 33);
  ASSERT_EQ(std::string(png.begin() + 37, png.begin() + 41), "IDAT");
  std::vector<uint8_t> raw(2 * (1 + 9));
  uLongf rawSize = raw.size();
  ASSERT_EQ(uncompress(raw.data(), &rawSize, png.data() + 41, idatLength), Z_OK);
  ASSERT_EQ(rawSize, raw.size());
  EXPECT_EQ(raw[0], 0);
  EXPECT_EQ(raw[1], 10);
  EXPECT_EQ(raw[10 + 1 + 6], 255);
  EXPECT_EQ(raw[10 + 1 + 8], 128);
  // The file ends with an empty IEND chunk.
  EXPECT_EQ(std::string(png.end() - 8, png.end() - 4), "IEND");
}

TEST(Png, WritesFileAndReportsUnwritablePath) {
  const auto dir = testing::scratchDir("png");
  writePng(RgbImage(4, 4), dir / "a.png");
  EXPECT_TRUE(std::filesystem::exists(dir / "a.png"));
  EXPECT_THROW(writePng(RgbImage(4, 4), dir / "missing-folder" / "a.png"), std::exception);
}

TEST(Image, DiscsAndLinesAreClipped) {
  RgbImage image(10, 10);
  image.fillDisc(0, 0, 3, {1, 2, 3});
  image.drawLine(-5, 5, 20, 5, {9, 9, 9});
  EXPECT_EQ(image.at(0, 0), (Rgb{1, 2, 3}));
  EXPECT_EQ(image.at(9, 5), (Rgb{9, 9, 9}));
  EXPECT_EQ(image.at(9, 9), (Rgb{}));
}

TEST(ScoreColor, RampEndsAndMiddle) {
  EXPECT_EQ(scoreColor(0.0), (Rgb{150, 20, 20}));
  EXPECT_EQ(scoreColor(0.5), (Rgb{240, 200, 30}));
  EXPECT_EQ(scoreColor(1.0), (Rgb{30, 170, 60}));
  EXPECT_EQ(scoreColor(7.0), scoreColor(1.0));
}

}  // namespace coinspect::eval
