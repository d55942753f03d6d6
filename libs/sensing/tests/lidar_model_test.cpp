// LiDAR models read from INI: the shipped models and the errors a user can make.
#include "coinspect/sensing/lidar_model.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "coinspect/core/config.h"
#include "coinspect/testing/input_errors.h"
#include "coinspect/testing/paths.h"

namespace coinspect::sensing {
namespace {

constexpr double kDeg = M_PI / 180.0;

const std::string kMinimal =
    "[head]\nchannels = 8\nvertical_min = -10\nvertical_max = 4\ncolumns = 100\nrate = 5\n"
    "min_range = 0.5\nmax_range = 30\n";

std::string errorFor(const std::string& extra) {
  return testing::messageOf(
      [&] { loadLidarModels(Config::fromText(kMinimal + extra, "lidars-test.ini")); });
}

TEST(LidarModels, ShippedFileHoldsTheReferenceVlp16OnItsServo) {
  const auto models = loadLidarModels(testing::sourceDir() / "share/coinspect/lidars.ini");
  ASSERT_EQ(models.count("vlp16-tilting"), 1u);
  EXPECT_EQ(models.count("vlp16"), 1u);
  EXPECT_GE(models.size(), 3u);
  const LidarSpec& s = models.at("vlp16-tilting");
  EXPECT_EQ(s.name, "vlp16-tilting");
  EXPECT_EQ(s.channels, 16);
  EXPECT_NEAR(s.verticalMin, -15 * kDeg, 1e-12);
  EXPECT_NEAR(s.verticalMax, 15 * kDeg, 1e-12);
  EXPECT_EQ(s.columns, 440);
  EXPECT_NEAR(s.azimuthMin, -M_PI, 1e-12);
  EXPECT_NEAR(s.azimuthMax, M_PI, 1e-12);
  EXPECT_DOUBLE_EQ(s.rate, 10.0);
  EXPECT_DOUBLE_EQ(s.minRange, 0.9);
  EXPECT_DOUBLE_EQ(s.maxRange, 50.0);
  EXPECT_DOUBLE_EQ(s.rangeNoiseSigma, 0.0);
  EXPECT_NEAR(s.tiltAmplitude, 90 * kDeg, 1e-12);
  EXPECT_DOUBLE_EQ(s.tiltPeriod, 8.0);
  EXPECT_TRUE(s.tilting());
  EXPECT_TRUE(s.mountOffset.isApprox(Eigen::Vector3d(0, 0, 0.2)));
  EXPECT_FALSE(models.at("vlp16").tilting());
  for (const auto& [name, spec] : models)
    EXPECT_GE(spec.channels, 16) << name;
}

TEST(LidarModels, OptionalKeysHaveTheirDefaults) {
  const auto models = loadLidarModels(Config::fromText(kMinimal, "lidars-test.ini"));
  const LidarSpec& s = models.at("head");
  EXPECT_EQ(s.rayCount(), 800);
  EXPECT_NEAR(s.azimuthMin, -M_PI, 1e-12);
  EXPECT_NEAR(s.azimuthMax, M_PI, 1e-12);
  EXPECT_DOUBLE_EQ(s.rangeNoiseSigma, 0.0);
  EXPECT_FALSE(s.tilting());
  EXPECT_TRUE(s.mountOffset.isZero());
  EXPECT_TRUE(s.sensorOffset.isZero());
  // 8 channels over 14 deg: 2 deg apart.
  EXPECT_NEAR(s.channelElevation(7), 4 * kDeg, 1e-12);
  EXPECT_NEAR(s.channelElevation(1), -8 * kDeg, 1e-12);
}

TEST(LidarModels, BadValuesNameFileAndKey) {
  const std::string unknown = errorFor("colums = 3\n");
  EXPECT_MENTIONS(unknown, "lidars-test.ini");
  EXPECT_MENTIONS(unknown, "colums");
  EXPECT_MENTIONS(errorFor("tilt_amplitude = 120\ntilt_period = 8\n"), "tilt_amplitude");
  EXPECT_MENTIONS(errorFor("tilt_amplitude = 90\n"), "tilt_period");
  EXPECT_MENTIONS(errorFor("range_noise_sigma = -1\n"), "range_noise_sigma");
  EXPECT_MENTIONS(errorFor("azimuth_min = 10\nazimuth_max = 0\n"), "azimuth_max");
  EXPECT_MENTIONS(errorFor("mount_offset = 1 2\n"), "mount_offset");
  EXPECT_MENTIONS(testing::messageOf([] {
                    loadLidarModels(Config::fromText(
                        "[x]\nchannels = 0\nvertical_min = 0\nvertical_max = 0\ncolumns = 1\n"
                        "rate = 1\nmin_range = 0\nmax_range = 1\n",
                        "t.ini"));
                  }),
                  "channels");
  EXPECT_MENTIONS(testing::messageOf([] {
                    loadLidarModels(Config::fromText(
                        "[x]\nchannels = 1\nvertical_min = 0\nvertical_max = 0\ncolumns = 1\n"
                        "rate = 1\nmin_range = 2\nmax_range = 1\n",
                        "t.ini"));
                  }),
                  "max_range");
  EXPECT_MENTIONS(
      testing::messageOf([] { loadLidarModels(Config::fromText("[x]\nchannels = 1\n", "t.ini")); }),
      "columns");
}

}  // namespace
}  // namespace coinspect::sensing
