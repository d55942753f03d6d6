#include "coinspect/vehicle/airframe.h"

#include <gtest/gtest.h>

#include <cmath>

#include "coinspect/core/error.h"
#include "coinspect/testing/files.h"
#include "coinspect/testing/input_errors.h"
#include "coinspect/testing/paths.h"

namespace coinspect::vehicle {
namespace {

using coinspect::testing::messageOf;

const std::filesystem::path shippedFile() {
  return coinspect::testing::sourceDir() / "share" / "coinspect" / "airframes.ini";
}

// The shipped file, as text, to derive broken variants from.
std::string shippedText() {
  return coinspect::testing::readFile(shippedFile());
}

std::filesystem::path writeVariant(const std::string& name, const std::string& text) {
  const auto path = coinspect::testing::scratchDir("airframe_" + name) / "airframes.ini";
  coinspect::testing::writeFile(path, text);
  return path;
}

std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const auto at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  return text.replace(at, from.size(), to);
}

TEST(Airframes, ShippedFileHasTheReferenceNumbers) {
  const auto airframes = loadAirframes(shippedFile());
  ASSERT_EQ(airframes.size(), 2u);
  const Airframe& explorer = airframes.at("explorer");
  EXPECT_EQ(explorer.name, "explorer");
  EXPECT_DOUBLE_EQ(explorer.mass, 2.5 + 0.8);
  EXPECT_DOUBLE_EQ(explorer.collisionRadius, 0.63);
  EXPECT_DOUBLE_EQ(explorer.tiltLimit, 45.0 * M_PI / 180.0);
  EXPECT_DOUBLE_EQ(explorer.gains.wXY, 2.0);
  EXPECT_DOUBLE_EQ(explorer.gains.zetaZ, 1.1);
  EXPECT_DOUBLE_EQ(explorer.minThrustAccel, 0.3 * 9.81);
  EXPECT_DOUBLE_EQ(explorer.maxThrustAccel, 2.0 * 9.81);
  EXPECT_DOUBLE_EQ(explorer.yawRateLimit, 90.0 * M_PI / 180.0);
  const Airframe& photographer = airframes.at("photographer");
  EXPECT_DOUBLE_EQ(photographer.mass, 1.5);
  EXPECT_DOUBLE_EQ(photographer.collisionRadius, 0.32);
  EXPECT_DOUBLE_EQ(photographer.tiltLimit, 55.0 * M_PI / 180.0);
  EXPECT_DOUBLE_EQ(photographer.gains.wXY, 2.5);
  EXPECT_DOUBLE_EQ(photographer.gains.kiZ, 0.07);
  EXPECT_DOUBLE_EQ(photographer.integralClamp, 10.0);
}

TEST(Airframes, UnknownKeyIsRejectedWithFileAndKey) {
  const auto path =
      writeVariant("unknown", replaced(shippedText(), "mass = 1.5", "mass = 1.5\nmas = 1.5"));
  const std::string message = messageOf([&] { loadAirframes(path); });
  EXPECT_MENTIONS(message, path.string());
  EXPECT_MENTIONS(message, "mas");
}

TEST(Airframes, NegativeMassIsRejectedWithFileAndKey) {
  const auto path = writeVariant("negative", replaced(shippedText(), "mass = 1.5", "mass = -1.5"));
  const std::string message = messageOf([&] { loadAirframes(path); });
  EXPECT_MENTIONS(message, path.string());
  EXPECT_MENTIONS(message, "[airframe.photographer] mass");
}

TEST(Airframes, MissingKeyAndBadTiltAreRejected) {
  const auto missing = writeVariant("missing", replaced(shippedText(), "w_z = 4.0", ""));
  EXPECT_MENTIONS(messageOf([&] { loadAirframes(missing); }), "[airframe.explorer] w_z");
  const auto tilt =
      writeVariant("tilt", replaced(shippedText(), "tilt_limit_deg = 55", "tilt_limit_deg = 95"));
  EXPECT_MENTIONS(messageOf([&] { loadAirframes(tilt); }),
                  "[airframe.photographer] tilt_limit_deg");
}

// A time constant far under the integration step made the non-stiff integrator fail (an abort,
// once) or crawl: such files are refused, naming the key.
TEST(Airframes, TimeConstantsUnderTenMillisecondsAreRejected) {
  const auto attitude =
      writeVariant("attitude", replaced(shippedText(), "attitude_time_constant = 0.1",
                                        "attitude_time_constant = 0.0000001"));
  const std::string message = messageOf([&] { loadAirframes(attitude); });
  EXPECT_MENTIONS(message, attitude.string());
  EXPECT_MENTIONS(message, "[airframe.explorer] attitude_time_constant");
  const auto drag = writeVariant(
      "drag", replaced(shippedText(), "drag_coefficient = 0.15", "drag_coefficient = 151"));
  EXPECT_MENTIONS(messageOf([&] { loadAirframes(drag); }),
                  "[airframe.photographer] drag_coefficient");
  // At the bound itself (1.5 kg / 150 N per m/s = 0.01 s) the file loads.
  const auto atBound = writeVariant(
      "bound", replaced(shippedText(), "drag_coefficient = 0.15", "drag_coefficient = 150"));
  EXPECT_EQ(loadAirframes(atBound).at("photographer").dragCoefficient, 150.0);
  Airframe tooFast;
  tooFast.attitudeTimeConstant = 0.001;
  EXPECT_THROW(validateAirframe(tooFast, "test"), InputError);
}

TEST(Airframes, ForeignSectionIsRejected) {
  const auto path = writeVariant("section", shippedText() + "\n[camera]\nfov = 1\n");
  EXPECT_MENTIONS(messageOf([&] { loadAirframes(path); }), "[camera]");
}

TEST(Airframes, ValidateRejectsImpossibleThrustClamp) {
  Airframe airframe;
  airframe.maxThrustAccel = 9.0;  // below g: it could never hover
  EXPECT_THROW(validateAirframe(airframe, "test"), InputError);
}

}  // namespace
}  // namespace coinspect::vehicle
