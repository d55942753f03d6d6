// What a strategy knows of its own robot from the start (StrategyContext): role, place in the
// fleet, the roster, the camera and its optics, the collision radius.
#pragma once

#include <cstddef>
#include <vector>

#include "coinspect/agent/strategy.h"
#include "coinspect/planning/camera_limits.h"
#include "coinspect/strategies/runtime/camera_aim.h"

namespace coinspect::strategies::runtime {

struct UnitInfo {
  explicit UnitInfo(const agent::StrategyContext& context)
      : role(context.role),
        self(context.unitIndex),
        fleet(context.fleet),
        camera(context.camera),
        radius(context.collisionRadius),
        optics(cameraOptics(context.camera)) {}

  agent::Role role;
  size_t self;  // fleet index
  std::vector<agent::FleetMember> fleet;
  agent::CameraInfo camera;
  double radius;  // m, collision radius
  planning::CameraOptics optics;
};

}  // namespace coinspect::strategies::runtime
