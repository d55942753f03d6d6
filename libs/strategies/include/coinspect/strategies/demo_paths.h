// `demo-paths`: every unit flies a fixed waypoint path from the config and aims its gimbal at a
// fixed world point, like the reference's demo flight test. No sensing is used: it exists to
// exercise the simulator end to end and to measure its speed.
//
// Config, one section per unit (units without a section stay where they are):
//   [demo-paths.<unit>]
//   waypoints     = x y z; x y z; ...   world frame, m (at least one)
//   speed         = 2.0                 cruise speed along the path, m/s (> 0)
//   loop          = false               after the last waypoint, start again at the first
//   loop_from     = 1                   with loop: the waypoint (1-based) the loop restarts at
//   takeoff       = true                climb vertically to the first waypoint's height first
//   gimbal_target = x y z               world point the camera looks at (optional)
//   gimbal_pitch  = 0                   deg, used when no gimbal_target (positive looks down)
//   yaw           = target              target | travel | <fixed angle in deg>
//   camera_offset = 0.2 0 -0.3          camera position in the body frame, m
//   rate          = 10                  decisions per second (>= 10: setpoints expire in 0.1 s)
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "coinspect/agent/strategy.h"
#include "coinspect/planning/viewpoint.h"

namespace coinspect::strategies {

using agent::Vec3;

struct DemoPathsOptions {
  std::vector<Vec3> waypoints;
  double speed = 2.0;
  bool loop = false;
  size_t loopFrom = 0;  // 0-based
  bool takeoff = true;
  std::optional<Vec3> gimbalTarget;
  double gimbalPitch = 0.0;  // rad
  enum class YawPolicy { Target, Travel, Fixed };
  YawPolicy yawPolicy = YawPolicy::Target;
  double fixedYaw = 0.0;  // rad
  Vec3 cameraOffset{0.2, 0.0, -0.3};
  double rate = 10.0;

  // Reads [demo-paths.<unit>]; std::nullopt when the section is absent. Throws InputError
  // naming the file and key for malformed values.
  static std::optional<DemoPathsOptions> read(const Config& config, const std::string& unit);
};

// Gimbal angles that put `target` on the optical axis: planning's (one convention everywhere).
using planning::AimAngles;
using planning::aimGimbal;

class DemoPaths : public agent::Strategy {
 public:
  // Without options the unit does nothing (no setpoint, no gimbal command).
  explicit DemoPaths(std::optional<DemoPathsOptions> options);

  agent::AgentCommand decide(const agent::AgentView& view) override;
  double decisionRate() const override;

  // Index of the path vertex the reference point is heading to (for tests).
  size_t targetVertex() const { return segment_ + 1; }

 private:
  void buildPath(const Vec3& start);
  void advance(const Vec3& position, double dt);

  std::optional<DemoPathsOptions> options_;
  std::vector<Vec3> path_;  // vertices: start, (take-off point), waypoints...
  size_t segment_ = 0;      // the reference point lies on path_[segment_] -> path_[segment_ + 1]
  double along_ = 0.0;      // distance along that segment, m
  bool finished_ = false;
  double lastTime_ = 0.0;
};

void registerDemoPaths(agent::StrategyRegistry& registry);

}  // namespace coinspect::strategies
