#include "coinspect/world/fleet.h"

#include <cmath>
#include <set>

#include "coinspect/core/error.h"
#include "coinspect/core/text.h"

namespace coinspect::world {

const char* toString(UnitRole role) {
  switch (role) {
    case UnitRole::GroundStation:
      return "gcs";
    case UnitRole::Explorer:
      return "explorer";
    case UnitRole::Photographer:
      return "photographer";
  }
  return "unknown";
}

UnitRole parseUnitRole(const std::string& text, const std::string& source) {
  const std::string role = toLower(trim(text));
  // "manager" is the reference network file's name for the ground station.
  if (role == "gcs" || role == "manager") return UnitRole::GroundStation;
  if (role == "explorer") return UnitRole::Explorer;
  if (role == "photographer") return UnitRole::Photographer;
  throw InputError(source, "role",
                   "'" + text + "' is not a unit role (gcs, manager, explorer, photographer)");
}

namespace {

void requireFinite(double value, const std::string& source, const std::string& where,
                   const char* what) {
  if (!std::isfinite(value)) throw InputError(source, where, std::string(what) + " is not finite");
}

void requirePositive(double value, const std::string& source, const std::string& where,
                     const char* what) {
  requireFinite(value, source, where, what);
  if (value <= 0.0)
    throw InputError(source, where,
                     std::string(what) + " must be positive, got " + std::to_string(value));
}

}  // namespace

void validateFleet(const std::vector<UnitSpec>& fleet, const std::string& source) {
  if (fleet.empty()) throw InputError(source, "fleet", "the fleet has no units");
  std::set<std::string> names;
  for (const auto& unit : fleet) {
    const std::string where = "unit '" + unit.name + "'";
    if (unit.name.empty()) throw InputError(source, where, "unit name is empty");
    // Names label recorded data and INI sections, which compare case-insensitively.
    if (!names.insert(toLower(unit.name)).second)
      throw InputError(source, where, "duplicate unit name");
    if (!unit.startPosition.allFinite())
      throw InputError(source, where, "start position is not finite");
    requireFinite(unit.startYaw, source, where, "start yaw");
    requireFinite(unit.antennaOffset, source, where, "antenna offset");
    if (unit.antennaOffset < 0.0)
      throw InputError(source, where, "antenna offset must not be negative");
    validateCamera(unit.camera, source, where);
  }
}

void validateCamera(const CameraSpec& c, const std::string& source, const std::string& where) {
  requirePositive(c.horizontalFov, source, where, "horizontal FOV");
  requirePositive(c.verticalFov, source, where, "vertical FOV");
  if (c.horizontalFov >= M_PI || c.verticalFov >= M_PI)
    throw InputError(source, where, "a field of view must be below 180 deg");
  if (!c.positionInBody.allFinite())
    throw InputError(source, where, "camera position is not finite");
  requirePositive(c.exposureTime, source, where, "exposure time");
  requirePositive(c.triggerInterval, source, where, "trigger interval");
  requirePositive(c.focalLength, source, where, "focal length");
  requirePositive(c.pixelSize, source, where, "pixel size");
  requirePositive(c.desiredMmPerPixel, source, where, "desired mm per pixel");
  requirePositive(c.gimbalPitchMax, source, where, "gimbal pitch limit");
  requirePositive(c.gimbalYawMax, source, where, "gimbal yaw limit");
  requirePositive(c.gimbalRateMax, source, where, "gimbal rate limit");
}

}  // namespace coinspect::world
