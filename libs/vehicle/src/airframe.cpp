#include "coinspect/vehicle/airframe.h"

#include <cmath>
#include <cstdio>
#include <string>

#include "coinspect/core/config.h"
#include "coinspect/core/error.h"

namespace coinspect::vehicle {
namespace {

constexpr double kGravity = 9.81;
// The model's fastest time constants (attitude_time_constant, mass / drag_coefficient) may not be
// shorter than this: CVODE's non-stiff method (chosen for speed) then takes ever smaller steps
// until a mission crawls, or fails (1e-7 s aborted the integration, 3e-7 s ran a 5 s mission for
// over a minute). Real multirotors are at 0.05 s and more; the shipped airframes at 0.1 s and 10 s
// or more.
constexpr double kMinTimeConstant = 0.01;
constexpr double kDegree = M_PI / 180.0;
const std::string kSectionPrefix = "airframe.";

// Values as written (std::to_string prints 1e-7 as 0.000000).
std::string shown(double value) {
  char text[32];
  std::snprintf(text, sizeof(text), "%g", value);
  return text;
}

// Reads one value and checks low < value < high (or <= when the bound is inclusive), naming the
// file and the key when it is not.
double readInRange(const Config& config, const std::string& section, const std::string& key,
                   double low, bool lowInclusive, double high) {
  const double value = config.getDouble(section, key);
  const bool aboveLow = lowInclusive ? value >= low : value > low;
  if (!aboveLow || value >= high) {
    throw InputError(config.source(), "[" + section + "] " + key,
                     shown(value) + " is outside " + (lowInclusive ? "[" : "(") + shown(low) +
                         ", " + shown(high) + ")");
  }
  return value;
}

double readPositive(const Config& config, const std::string& section, const std::string& key) {
  return readInRange(config, section, key, 0.0, false, HUGE_VAL);
}

double readNonNegative(const Config& config, const std::string& section, const std::string& key) {
  return readInRange(config, section, key, 0.0, true, HUGE_VAL);
}

Airframe readAirframe(const Config& config, const std::string& section) {
  Airframe a;
  a.name = section.substr(kSectionPrefix.size());
  a.mass = readPositive(config, section, "mass");
  a.collisionRadius = readPositive(config, section, "collision_radius");
  a.tiltLimit = readInRange(config, section, "tilt_limit_deg", 0.0, false, 90.0) * kDegree;
  a.maxAccelerationXY = readPositive(config, section, "max_accel_xy");
  a.minThrustAccel = readNonNegative(config, section, "min_thrust_accel_g") * kGravity;
  a.maxThrustAccel = readPositive(config, section, "max_thrust_accel_g") * kGravity;
  if (a.maxThrustAccel <= kGravity || a.minThrustAccel >= kGravity) {
    throw InputError(config.source(), "[" + section + "] min_thrust_accel_g/max_thrust_accel_g",
                     "the vertical clamp must contain 1 g (min < 1 < max), or it cannot hover");
  }
  a.yawRateLimit = readPositive(config, section, "yaw_rate_limit_deg") * kDegree;
  a.dragCoefficient = readNonNegative(config, section, "drag_coefficient");
  a.attitudeTimeConstant =
      readInRange(config, section, "attitude_time_constant", kMinTimeConstant, true, HUGE_VAL);
  if (a.dragCoefficient * kMinTimeConstant > a.mass) {
    throw InputError(config.source(), "[" + section + "] drag_coefficient",
                     shown(a.dragCoefficient) + " N per m/s on " + shown(a.mass) +
                         " kg: the velocity's time constant (mass / drag_coefficient) is under "
                         "0.01 s; at most 100 N per m/s per kg");
  }
  a.tiltRateLimit = readPositive(config, section, "tilt_rate_limit_deg") * kDegree;
  a.gains.wXY = readPositive(config, section, "w_xy");
  a.gains.wZ = readPositive(config, section, "w_z");
  a.gains.zetaXY = readPositive(config, section, "zeta_xy");
  a.gains.zetaZ = readPositive(config, section, "zeta_z");
  a.gains.kiXY = readNonNegative(config, section, "ki_xy");
  a.gains.kiZ = readNonNegative(config, section, "ki_z");
  a.gains.yawKp = readPositive(config, section, "yaw_kp");
  a.gains.yawKi = readNonNegative(config, section, "yaw_ki");
  a.integralClamp = readNonNegative(config, section, "integral_clamp");
  a.yawIntegralClamp = readNonNegative(config, section, "yaw_integral_clamp");
  return a;
}

void require(bool ok, const std::string& source, const std::string& field,
             const std::string& what) {
  if (!ok) throw InputError(source, field, what);
}

}  // namespace

void validateAirframe(const Airframe& a, const std::string& source) {
  const auto finitePositive = [](double v) { return std::isfinite(v) && v > 0.0; };
  const auto finiteNonNegative = [](double v) { return std::isfinite(v) && v >= 0.0; };
  const std::string where = "airframe '" + a.name + "' ";
  require(finitePositive(a.mass), source, where + "mass", "must be > 0 kg");
  require(finitePositive(a.collisionRadius), source, where + "collisionRadius", "must be > 0 m");
  require(finitePositive(a.tiltLimit) && a.tiltLimit < M_PI / 2, source, where + "tiltLimit",
          "must be in (0, pi/2) rad");
  require(finitePositive(a.maxAccelerationXY), source, where + "maxAccelerationXY", "must be > 0");
  require(finiteNonNegative(a.minThrustAccel) && a.minThrustAccel < kGravity &&
              std::isfinite(a.maxThrustAccel) && a.maxThrustAccel > kGravity,
          source, where + "minThrustAccel/maxThrustAccel", "must satisfy 0 <= min < g < max");
  require(finitePositive(a.yawRateLimit), source, where + "yawRateLimit", "must be > 0");
  require(finiteNonNegative(a.dragCoefficient), source, where + "dragCoefficient", "must be >= 0");
  require(std::isfinite(a.attitudeTimeConstant) && a.attitudeTimeConstant >= kMinTimeConstant,
          source, where + "attitudeTimeConstant", "must be >= 0.01 s");
  require(a.dragCoefficient * kMinTimeConstant <= a.mass, source, where + "dragCoefficient",
          "mass / dragCoefficient must be >= 0.01 s");
  require(finitePositive(a.tiltRateLimit), source, where + "tiltRateLimit", "must be > 0");
  const ControllerGains& g = a.gains;
  require(finitePositive(g.wXY) && finitePositive(g.wZ) && finitePositive(g.zetaXY) &&
              finitePositive(g.zetaZ) && finiteNonNegative(g.kiXY) && finiteNonNegative(g.kiZ) &&
              finitePositive(g.yawKp) && finiteNonNegative(g.yawKi),
          source, where + "gains", "frequencies, damping and yawKp must be > 0, ki >= 0");
  require(finiteNonNegative(a.integralClamp) && finiteNonNegative(a.yawIntegralClamp), source,
          where + "integralClamp/yawIntegralClamp", "must be >= 0");
}

std::map<std::string, Airframe> loadAirframes(const std::filesystem::path& ini) {
  const Config config = Config::fromFile(ini);
  std::map<std::string, Airframe> airframes;
  for (const std::string& section : config.sections()) {
    if (section.rfind(kSectionPrefix, 0) != 0 || section.size() == kSectionPrefix.size()) {
      throw InputError(config.source(), "[" + section + "]",
                       "unknown section (expected [airframe.<name>])");
    }
    Airframe airframe = readAirframe(config, section);
    airframes.emplace(airframe.name, std::move(airframe));
  }
  if (airframes.empty()) throw InputError(config.source(), "", "no [airframe.<name>] section");
  config.requireAllKeysUsed();
  for (const auto& [name, airframe] : airframes)
    validateAirframe(airframe, config.source());
  return airframes;
}

}  // namespace coinspect::vehicle
