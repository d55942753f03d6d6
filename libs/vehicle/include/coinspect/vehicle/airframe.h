// A multirotor airframe: mass, size and the tracking controller's limits and gains (plain data).
//
// The numbers of the reference (CARIC's unicon controller and its two airframes) live in
// share/coinspect/airframes.ini; doc/config.md lists every key with its unit.
#pragma once

#include <filesystem>
#include <map>
#include <string>

namespace coinspect::vehicle {

// Gains of a_cmd = w^2 (p_ref - p) + 2 zeta w (v_ref - v) + a_ref + ki * sum(p_ref - p) (+g on z),
// where the sum adds one position error per 20 Hz control tick (no dt, as in the reference).
struct ControllerGains {
  double wXY = 2.0;     // rad/s, natural frequency of x and y
  double wZ = 4.0;      // rad/s
  double zetaXY = 1.0;  // damping ratio of x and y
  double zetaZ = 1.1;
  double kiXY = 0.03;  // 1/s^2 per accumulated metre
  double kiZ = 0.07;
  double yawKp = 2.0;  // 1/s: yaw rate = yawKp * yaw error + yawKi * accumulated yaw error
  double yawKi = 0.02;
};

struct Airframe {
  std::string name;
  double mass = 1.5;                // kg, everything that flies (body + payload)
  double collisionRadius = 0.32;    // m, sphere around the body centre used by the sim
  double tiltLimit = 0.96;          // rad, limit of |roll| and of |pitch| separately (reference)
  double maxAccelerationXY = 10.0;  // m/s^2, clamp of each horizontal command component
  double minThrustAccel = 2.943;    // m/s^2 (absolute), lower clamp of the vertical command incl. g
  double maxThrustAccel = 19.62;    // m/s^2 (absolute), upper clamp of the vertical command incl. g
  double yawRateLimit = 1.5708;     // rad/s
  double dragCoefficient = 0.15;    // N per m/s, linear rotor drag on the velocity
  double attitudeTimeConstant = 0.1;  // s, first-order response of roll, pitch and yaw rate
  double tiltRateLimit = 4.0;         // rad/s, bound of the roll and pitch rates
  ControllerGains gains;
  double integralClamp = 10.0;     // m, bound of each component of the accumulated position error
  double yawIntegralClamp = 1.57;  // rad, bound of the accumulated yaw error
};

// Throws InputError naming `source` and the field when a value is out of its range (non-positive
// mass, tilt limit outside (0, 90) deg, min thrust above max thrust, ...).
void validateAirframe(const Airframe& airframe, const std::string& source);

// Reads every [airframe.<name>] section of an INI file (keys in doc/config.md, all required) into
// a map keyed by <name>. Unknown sections or keys, malformed or out-of-range values throw
// InputError naming the file and the "[section] key".
std::map<std::string, Airframe> loadAirframes(const std::filesystem::path& ini);

}  // namespace coinspect::vehicle
