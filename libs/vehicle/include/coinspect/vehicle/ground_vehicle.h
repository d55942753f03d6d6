// The ground station: static (CARIC) or a ground vehicle driving at most maxSpeed toward a target
// point (SLEI3D's mobile GCS). Kinematic: it drives straight at full speed, stops on the target,
// keeps its height, faces its direction of travel and is never airborne. It cannot see: whoever
// moves it checks the way and calls stopAt() when the move crossed an obstacle.
#pragma once

#include "coinspect/vehicle/setpoint.h"
#include "coinspect/vehicle/vehicle_state.h"

namespace coinspect::vehicle {

class GroundVehicle {
 public:
  // maxSpeed in m/s (0 = static); throws InputError when negative or not finite.
  GroundVehicle(const Vec3& startPosition, double startYaw, double maxSpeed);

  // Drive toward `target` (its z is ignored). Non-finite targets are rejected and counted.
  bool setTarget(const Vec3& target);
  void advance(double dt);
  // An obstacle was in the way of the last advance: the vehicle is put back at `position` (where
  // it still was clear), at rest, and gives up its target (a new one moves it again).
  void stopAt(const Vec3& position);
  long long obstacleStops() const { return obstacleStops_; }

  const VehicleState& state() const { return state_; }
  double maxSpeed() const { return maxSpeed_; }
  const Vec3& target() const { return target_; }
  bool airborne() const { return false; }
  long long rejectedCommands() const { return rejected_; }

 private:
  double maxSpeed_;
  Vec3 target_;
  VehicleState state_;
  long long rejected_ = 0;
  long long obstacleStops_ = 0;
};

}  // namespace coinspect::vehicle
