// The fleet of a scenario: units, their roles, cameras and start poses (plain data).
#pragma once

#include <string>
#include <vector>

#include "coinspect/world/mesh.h"

namespace coinspect::world {

enum class UnitRole { GroundStation, Explorer, Photographer };

const char* toString(UnitRole role);
// "gcs"/"manager", "explorer", "photographer"; throws InputError naming `source` otherwise.
UnitRole parseUnitRole(const std::string& text, const std::string& source);

// One row of a CARIC network file, in SI units (angles in radians).
struct CameraSpec {
  double horizontalFov = 80.0 * M_PI / 180.0;
  double verticalFov = 60.0 * M_PI / 180.0;
  Vec3 positionInBody{0.2, 0.0, -0.3};
  double exposureTime = 0.001;     // s
  double triggerInterval = 0.1;    // s
  double focalLength = 0.016;      // m
  double pixelSize = 4.35e-6;      // m
  double desiredMmPerPixel = 2.0;  // r_des, mm/px
  double gimbalPitchMax = 80.0 * M_PI / 180.0;
  double gimbalYawMax = 90.0 * M_PI / 180.0;
  double gimbalRateMax = 60.0 * M_PI / 180.0;  // rad/s
};

struct UnitSpec {
  std::string name;
  UnitRole role = UnitRole::Photographer;
  Vec3 startPosition = Vec3::Zero();
  double startYaw = 0.0;       // rad
  double antennaOffset = 0.1;  // m, ppcom antenna offset along each body axis
  CameraSpec camera;
};

// Throws InputError naming `source` for duplicate names, no units, more than one unit with the
// same name, non-finite values, non-positive camera parameters or FOV >= 180 deg.
void validateFleet(const std::vector<UnitSpec>& fleet, const std::string& source);

// The camera part of validateFleet (non-positive parameters, FOV >= 180 deg, a non-finite
// position), for readers that can name the line: throws InputError(source, where, ...).
void validateCamera(const CameraSpec& camera, const std::string& source, const std::string& where);

}  // namespace coinspect::world
