#include "coinspect/vehicle/ground_vehicle.h"

#include <cmath>
#include <string>

#include "coinspect/core/error.h"

namespace coinspect::vehicle {

GroundVehicle::GroundVehicle(const Vec3& startPosition, double startYaw, double maxSpeed)
    : maxSpeed_(maxSpeed), target_(startPosition) {
  if (!std::isfinite(maxSpeed) || maxSpeed < 0.0) {
    throw InputError("GroundVehicle", "maxSpeed",
                     std::to_string(maxSpeed) + " must be a finite speed >= 0 m/s");
  }
  if (!startPosition.allFinite() || !std::isfinite(startYaw)) {
    throw InputError("GroundVehicle", "start pose", "must be finite");
  }
  state_.position = startPosition;
  state_.yaw = startYaw;
}

bool GroundVehicle::setTarget(const Vec3& target) {
  if (!target.allFinite()) {
    ++rejected_;
    return false;
  }
  target_ = Vec3(target.x(), target.y(), state_.position.z());
  return true;
}

void GroundVehicle::advance(double dt) {
  COINSPECT_ASSERT(std::isfinite(dt) && dt >= 0.0);
  state_.time += dt;
  const Vec3 toTarget = target_ - state_.position;
  const double distance = toTarget.norm();
  const double reach = maxSpeed_ * dt;
  if (distance <= 0.0 || reach <= 0.0) {
    state_.velocity.setZero();
    return;
  }
  if (distance <= reach) {
    state_.position = target_;
    state_.velocity = toTarget / dt;  // the average over this step (below maxSpeed)
  } else {
    state_.position += toTarget * (reach / distance);
    state_.velocity = toTarget * (maxSpeed_ / distance);
  }
  state_.yaw = std::atan2(toTarget.y(), toTarget.x());
}

void GroundVehicle::stopAt(const Vec3& position) {
  COINSPECT_ASSERT(position.allFinite());
  state_.position = position;
  state_.velocity.setZero();
  target_ = position;
  ++obstacleStops_;
}

}  // namespace coinspect::vehicle
