// LiDAR models: the geometry of a spinning multi-channel head and of the mount that carries it,
// read from an INI file (share/coinspect/lidars.ini; keys in doc/config.md).
//
// Frames: the sensor frame has x forward, z up along the spin axis; a ray of elevation e and
// azimuth a points along (cos e cos a, cos e sin a, sin e). The mount may tilt the head about the
// body x axis (the CARIC explorers' servo, doc/sensors.md).
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <cmath>
#include <filesystem>
#include <map>
#include <string>

namespace coinspect {
class Config;
}

namespace coinspect::sensing {

struct LidarSpec {
  std::string name;
  int channels = 16;
  double verticalMin = -15.0 * M_PI / 180.0;  // rad, elevation of the lowest channel
  double verticalMax = 15.0 * M_PI / 180.0;   // rad, elevation of the highest channel
  int columns = 440;
  // Azimuths of the first and last column (rad). Like the reference (Gazebo's ray sensor), both
  // ends are sampled: with -pi..pi the first and last columns coincide.
  double azimuthMin = -M_PI;
  double azimuthMax = M_PI;
  double rate = 10.0;            // sweeps per second
  double minRange = 0.9;         // m; returns must satisfy minRange < r < maxRange
  double maxRange = 50.0;        // m
  double rangeNoiseSigma = 0.0;  // m, Gaussian on the range; 0 = exact
  double tiltAmplitude = 0.0;    // rad, servo limit (+-); 0 = fixed mount
  double tiltPeriod = 0.0;       // s, servo period; 0 = fixed mount
  Eigen::Vector3d mountOffset = Eigen::Vector3d::Zero();   // servo pivot in the body frame
  Eigen::Vector3d sensorOffset = Eigen::Vector3d::Zero();  // sensor origin in the tilted frame

  int rayCount() const { return channels * columns; }
  bool tilting() const { return tiltAmplitude > 0.0 && tiltPeriod > 0.0; }
  // Elevation of channel c (0 = lowest) and azimuth of column k, both rad.
  double channelElevation(int channel) const;
  double columnAzimuth(int column) const;
};

// Reads every section of the file as one model named after the section. Strict: unknown keys,
// bad values and impossible models throw InputError naming the file and "[section] key".
std::map<std::string, LidarSpec> loadLidarModels(const std::filesystem::path& path);
std::map<std::string, LidarSpec> loadLidarModels(const Config& config);

// The servo angle (rad, about body x) at simulated time t (s). The reference drives the joint at
// +-2 pi / period rad/s, positive while sin(2 pi t / period) > 0, and the joint stops at
// +-amplitude: with the CARIC values (90 deg, 8 s) the head rises to +90 deg in 2 s, rests there
// until 4 s, then sweeps a triangle wave between -90 and +90 deg with period 8 s.
// Requires amplitude <= 90 deg (checked when loading). 0 for a fixed mount.
double servoTiltAngle(const LidarSpec& spec, double time);

// Sensor pose in the body frame at time t: translate(mountOffset) * Rx(tilt) *
// translate(sensorOffset).
Eigen::Isometry3d lidarPoseInBody(const LidarSpec& spec, double time);

}  // namespace coinspect::sensing
