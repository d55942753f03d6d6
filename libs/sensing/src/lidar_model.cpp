#include "coinspect/sensing/lidar_model.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "coinspect/core/config.h"
#include "coinspect/core/error.h"

namespace coinspect::sensing {

namespace {

constexpr double kDeg = M_PI / 180.0;

std::string formatValue(double value) {
  std::ostringstream text;
  text << value;
  return text.str();
}

// Reads one model; every check names the key whose value is wrong.
LidarSpec readModel(const Config& config, const std::string& section) {
  const auto fail = [&](const std::string& key, const std::string& what) {
    throw InputError(config.source(), "[" + section + "] " + key, what);
  };
  const auto positiveInt = [&](const std::string& key) {
    const long long value = config.getInt(section, key);
    if (value < 1 || value > 100000)
      fail(key, "must be in 1..100000, got " + std::to_string(value));
    return static_cast<int>(value);
  };
  const auto finite = [&](const std::string& key, double value) {
    if (!std::isfinite(value)) fail(key, "must be finite, got " + formatValue(value));
    return value;
  };

  LidarSpec spec;
  spec.name = section;
  spec.channels = positiveInt("channels");
  spec.columns = positiveInt("columns");
  const double verticalMin = finite("vertical_min", config.getDouble(section, "vertical_min"));
  const double verticalMax = finite("vertical_max", config.getDouble(section, "vertical_max"));
  if (verticalMin < -90.0 || verticalMax > 90.0 || verticalMin > verticalMax)
    fail("vertical_max", "need -90 <= vertical_min <= vertical_max <= 90 deg, got " +
                             formatValue(verticalMin) + " and " + formatValue(verticalMax));
  spec.verticalMin = verticalMin * kDeg;
  spec.verticalMax = verticalMax * kDeg;
  const double azimuthMin = finite("azimuth_min", config.getDouble(section, "azimuth_min", -180.0));
  const double azimuthMax = finite("azimuth_max", config.getDouble(section, "azimuth_max", 180.0));
  if (azimuthMin > azimuthMax || azimuthMax - azimuthMin > 360.0)
    fail("azimuth_max", "need azimuth_min <= azimuth_max <= azimuth_min + 360 deg, got " +
                            formatValue(azimuthMin) + " and " + formatValue(azimuthMax));
  spec.azimuthMin = azimuthMin * kDeg;
  spec.azimuthMax = azimuthMax * kDeg;
  spec.rate = finite("rate", config.getDouble(section, "rate"));
  if (!(spec.rate > 0.0)) fail("rate", "must be positive, got " + formatValue(spec.rate));
  spec.minRange = finite("min_range", config.getDouble(section, "min_range"));
  spec.maxRange = finite("max_range", config.getDouble(section, "max_range"));
  if (spec.minRange < 0.0 || !(spec.maxRange > spec.minRange))
    fail("max_range", "need 0 <= min_range < max_range, got " + formatValue(spec.minRange) +
                          " and " + formatValue(spec.maxRange));
  spec.rangeNoiseSigma =
      finite("range_noise_sigma", config.getDouble(section, "range_noise_sigma", 0.0));
  if (spec.rangeNoiseSigma < 0.0)
    fail("range_noise_sigma", "must not be negative, got " + formatValue(spec.rangeNoiseSigma));
  const double amplitude =
      finite("tilt_amplitude", config.getDouble(section, "tilt_amplitude", 0.0));
  spec.tiltPeriod = finite("tilt_period", config.getDouble(section, "tilt_period", 0.0));
  if (amplitude < 0.0 || amplitude > 90.0)
    fail("tilt_amplitude", "must be in 0..90 deg, got " + formatValue(amplitude));
  if (spec.tiltPeriod < 0.0)
    fail("tilt_period", "must not be negative, got " + formatValue(spec.tiltPeriod));
  if ((amplitude > 0.0) != (spec.tiltPeriod > 0.0))
    fail("tilt_period",
         "tilt_amplitude and tilt_period must both be 0 (fixed mount) or both "
         "positive, got " +
             formatValue(amplitude) + " and " + formatValue(spec.tiltPeriod));
  spec.tiltAmplitude = amplitude * kDeg;
  spec.mountOffset = config.getVector3(section, "mount_offset", Eigen::Vector3d::Zero());
  spec.sensorOffset = config.getVector3(section, "sensor_offset", Eigen::Vector3d::Zero());
  if (!spec.mountOffset.allFinite()) fail("mount_offset", "must be finite");
  if (!spec.sensorOffset.allFinite()) fail("sensor_offset", "must be finite");
  return spec;
}

}  // namespace

double LidarSpec::channelElevation(int channel) const {
  if (channels == 1) return verticalMin;
  return verticalMin + channel * (verticalMax - verticalMin) / (channels - 1);
}

double LidarSpec::columnAzimuth(int column) const {
  if (columns == 1) return azimuthMin;
  return azimuthMin + column * (azimuthMax - azimuthMin) / (columns - 1);
}

std::map<std::string, LidarSpec> loadLidarModels(const Config& config) {
  std::map<std::string, LidarSpec> models;
  for (const auto& section : config.sections())
    models.emplace(section, readModel(config, section));
  if (models.empty()) throw InputError(config.source(), "file", "defines no LiDAR model");
  config.requireAllKeysUsed();
  return models;
}

std::map<std::string, LidarSpec> loadLidarModels(const std::filesystem::path& path) {
  return loadLidarModels(Config::fromFile(path));
}

double servoTiltAngle(const LidarSpec& spec, double time) {
  if (!spec.tilting()) return 0.0;
  const double a = spec.tiltAmplitude;
  const double rate = 2.0 * M_PI / spec.tiltPeriod;
  const double half = 0.5 * spec.tiltPeriod;
  // Half period k moves upwards when k is even (sin > 0). A half period moves pi rad, at least
  // 2a, so each one after the first starts at a limit: +a before a descent, -a before a climb.
  const double k = std::floor(time / half);
  const double tau = time - k * half;
  if (k <= 0.0) return std::clamp(rate * time, -a, a);
  const bool rising = std::fmod(k, 2.0) == 0.0;
  return rising ? std::min(-a + rate * tau, a) : std::max(a - rate * tau, -a);
}

Eigen::Isometry3d lidarPoseInBody(const LidarSpec& spec, double time) {
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.translate(spec.mountOffset);
  pose.rotate(Eigen::AngleAxisd(servoTiltAngle(spec, time), Eigen::Vector3d::UnitX()));
  pose.translate(spec.sensorOffset);
  return pose;
}

}  // namespace coinspect::sensing
