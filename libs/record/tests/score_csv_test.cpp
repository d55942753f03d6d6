#include "coinspect/record/score_csv.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "coinspect/testing/files.h"
#include "coinspect/testing/input_errors.h"

namespace coinspect::record {

namespace {

std::filesystem::path scratch(const std::string& name) {
  const auto folder = std::filesystem::temp_directory_path() / "coinspect_score_csv_test";
  std::filesystem::create_directories(folder);
  return folder / name;
}

world::InterestPointSet threePoints() {
  std::vector<world::InterestPoint> points(3);
  points[0].position = {1.0, 2.5, -3.0};
  points[0].normal = {0.0, 0.0, 1.0};
  points[1].position = {4.0, 5.0, 6.0};
  points[1].normal = {1.0, 0.0, 0.0};
  points[2].position = {-0.5, 0.25, 8.0};
  points[2].normal = {0.0, -1.0, 0.0};
  return world::InterestPointSet(points);
}

}  // namespace

TEST(CaricScoreCsv, WritesTheReferenceHeaderColumnOrderAndSeparators) {
  const auto path = scratch("format.csv");
  writeCaricScoreCsv(path, threePoints(), {0.5f, 0.0f, 0.25f});
  // Header as MissionManager.cpp writes it; only detected points; x, y, z, nx, ny, nz, score,
  // idx with ", " between columns and exact short values for exactly representable floats.
  EXPECT_EQ(testing::readFile(path),
            "x, y, z, nx, ny, nz, score, idx\n"
            "1, 2.5, -3, 0, 0, 1, 0.5, 0\n"
            "-0.5, 0.25, 8, 0, -1, 0, 0.25, 2\n");
}

TEST(CaricScoreCsv, PrintsSixteenSignificantDigitsOfTheSinglePrecisionValue) {
  const auto path = scratch("precision.csv");
  writeCaricScoreCsv(path, threePoints(), {0.1f, 0.0f, 0.0f});
  // 0.1f is 0.100000001490116119384765625; 16 significant digits of it.
  EXPECT_EQ(testing::readFile(path),
            "x, y, z, nx, ny, nz, score, idx\n1, 2.5, -3, 0, 0, 1, 0.1000000014901161, 0\n");
}

TEST(CaricScoreCsv, ReadsBackValuesIndicesAndTotal) {
  const auto path = scratch("roundtrip.csv");
  const auto points = threePoints();
  const std::vector<float> values = {0.75f, 0.3f, 0.0f};
  writeCaricScoreCsv(path, points, values, ScoreCsvRows::All);
  const auto rows = readCaricScoreCsv(path);
  ASSERT_EQ(rows.size(), 3u);
  for (size_t i = 0; i < rows.size(); ++i) {
    EXPECT_EQ(rows[i].index, i);
    EXPECT_EQ(rows[i].x, static_cast<float>(points[i].position.x()));
    EXPECT_EQ(rows[i].y, static_cast<float>(points[i].position.y()));
    EXPECT_EQ(rows[i].z, static_cast<float>(points[i].position.z()));
    EXPECT_EQ(rows[i].nx, static_cast<float>(points[i].normal.x()));
    EXPECT_EQ(rows[i].ny, static_cast<float>(points[i].normal.y()));
    EXPECT_EQ(rows[i].nz, static_cast<float>(points[i].normal.z()));
    EXPECT_EQ(rows[i].score, values[i]);  // 16 digits restore a float exactly
  }
  EXPECT_DOUBLE_EQ(totalScore(rows), double(0.75f) + double(0.3f));
}

TEST(CaricScoreCsv, ReadsTheReferenceSpellingWithoutSpaces) {
  const auto path = scratch("compact.csv");
  testing::writeFile(path, "x,y,z,nx,ny,nz,score,idx\r\n1,2,3,0,0,1,0.25,7\r\n");
  const auto rows = readCaricScoreCsv(path);
  ASSERT_EQ(rows.size(), 1u);
  EXPECT_EQ(rows[0].index, 7u);
  EXPECT_EQ(rows[0].score, 0.25f);
}

TEST(CaricScoreCsv, ErrorsNameTheFileAndLine) {
  const auto path = scratch("bad.csv");
  testing::writeFile(path, "x, y, z, nx, ny, nz, score, idx\n1, 2, 3, 0, 0, 1, 0.5, 0\n1, 2, 3\n");
  auto message = testing::messageOf([&] { readCaricScoreCsv(path); });
  EXPECT_MENTIONS(message, "bad.csv");
  EXPECT_MENTIONS(message, "line 3");
  testing::writeFile(path, "a, b\n");
  message = testing::messageOf([&] { readCaricScoreCsv(path); });
  EXPECT_MENTIONS(message, "line 1");
  testing::writeFile(path, "x, y, z, nx, ny, nz, score, idx\n1, 2, 3, 0, 0, 1, zero, 0\n");
  message = testing::messageOf([&] { readCaricScoreCsv(path); });
  EXPECT_MENTIONS(message, "line 2");
  EXPECT_MENTIONS(message, "zero");
}

TEST(CaricScoreCsv, RejectsValuesThatDoNotMatchThePoints) {
  const auto message = testing::messageOf(
      [&] { writeCaricScoreCsv(scratch("mismatch.csv"), threePoints(), {1.0f}); });
  EXPECT_MENTIONS(message, "1 values for 3 interest points");
}

}  // namespace coinspect::record
