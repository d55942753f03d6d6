// The 20 Hz position tracking controller of the reference (CARIC's unicon), as a pure function of
// the command, the time and the vehicle state: it turns a Setpoint into roll, pitch, yaw rate and
// thrust. See setpoint.h for the command semantics and doc/architecture.md ("vehicle").
#pragma once

#include <optional>

#include "coinspect/vehicle/airframe.h"
#include "coinspect/vehicle/setpoint.h"
#include "coinspect/vehicle/vehicle_state.h"

namespace coinspect::vehicle {

constexpr double kControlPeriod = 0.05;  // s: the controller runs at t = k * 0.05 exactly
constexpr double kCommandTimeout = 0.1;  // s: older commands => hold position

// What the controller asks of the attitude loop, held constant until the next tick.
struct AttitudeCommand {
  double roll = 0.0;     // rad, ZYX, within +-tiltLimit
  double pitch = 0.0;    // rad, ZYX, within +-tiltLimit
  double yawRate = 0.0;  // rad/s, within +-yawRateLimit
  double thrust = 0.0;   // N, along body z, >= 0
};

enum class ControlMode { Idle, Tracking, YawOnly, Holding };

// Everything the controller remembers between ticks (plain data: copy it to save/restore).
struct ControllerMemory {
  ControlMode mode = ControlMode::Idle;
  Setpoint command;                      // the last accepted command
  double commandTime = 0.0;              // s, when it was accepted
  bool commandPending = false;           // accepted since the last tick
  Setpoint reference;                    // what the loop tracks (the command, or a hold)
  Vec3 positionErrorSum = Vec3::Zero();  // m, clamped per axis to +-integralClamp
  double yawErrorSum = 0.0;              // rad, clamped to +-yawIntegralClamp
  Vec3 lastBodyX = Vec3::UnitX();        // fallback when the thrust direction is degenerate
};

class TrackingController {
 public:
  explicit TrackingController(const Airframe& airframe) : airframe_(airframe) {}

  // Stores a command received at `time` (the caller checks it is finite).
  void setCommand(const Setpoint& command, double time);
  // One control tick at `time`; nullopt while no command was ever received (motors idle).
  std::optional<AttitudeCommand> tick(double time, const VehicleState& state);

  const ControllerMemory& memory() const { return memory_; }
  void setMemory(const ControllerMemory& memory) { memory_ = memory; }
  const Airframe& airframe() const { return airframe_; }

 private:
  void updateMode(double time, const VehicleState& state);
  Vec3 accelerationCommand(const VehicleState& state);

  Airframe airframe_;
  ControllerMemory memory_;
};

// Angle wrapped to (-pi, pi].
double wrapAngle(double angle);

}  // namespace coinspect::vehicle
