// A multirotor UAV: the reference's 20 Hz tracking controller flying a rigid body integrated by
// SUNDIALS CVODE (or a fixed-step RK4 reference), with ground contact and a kill switch.
//
// Time: advance(dt) moves simulated time forward; the controller runs inside it at t = k * 0.05 s
// exactly (k integer), whatever dt is, and its output is held until the next tick. Before the
// first command the motors idle and the vehicle stays at its start position (on the ground).
// The ground (z = groundZ) stops a descending vehicle without bounce; a vehicle whose thrust cannot
// lift it rests there. kill(): motors off, ballistic fall (gravity only), rest on the ground.
// Not copyable (it owns a CVODE solver); snapshot()/restore() copy everything that matters, and a
// restored vehicle continues bit-identically to the original. A snapshot holds no airframe, ground
// height or integrator options: restore it into a vehicle constructed with the same ones.
#pragma once

#include <memory>

#include "coinspect/vehicle/airframe.h"
#include "coinspect/vehicle/setpoint.h"
#include "coinspect/vehicle/tracking_controller.h"
#include "coinspect/vehicle/vehicle_state.h"

namespace coinspect::vehicle {

enum class Integrator { Cvode, Rk4 };

struct IntegratorOptions {
  Integrator method = Integrator::Cvode;
  // Chosen by a convergence test against RK4 at 0.1 ms (bench/vehicle_bench.cpp,
  // doc/benchmarks.md).
  double relativeTolerance = 1e-6;
  double absoluteTolerance = 1e-8;
  double cvodeInitialStep = 1e-3;  // s
  double rk4Step = 1e-3;           // s, fixed step of the RK4 reference
};

enum class FlightPhase { Idle, Flying, Dead };

// Everything that evolves, as plain data (copyable, comparable by value).
struct MultirotorSnapshot {
  FlightPhase phase = FlightPhase::Idle;
  double time = 0.0;
  long long nextTick = 0;    // the next control tick is at nextTick * kControlPeriod
  double state[10] = {};     // p, v, roll, pitch, yaw (unwrapped), yaw rate
  double segmentTime = 0.0;  // where the integrator was last (re)started
  double segmentState[10] = {};
  AttitudeCommand input;
  bool grounded = false;
  ControllerMemory controller;
  double killTime = 0.0;  // for the ballistic fall
  Vec3 killPosition = Vec3::Zero();
  Vec3 killVelocity = Vec3::Zero();
  bool resting = false;  // dead and lying on the ground
  long long rejectedCommands = 0;
};

class OdeStepper;

class Multirotor {
 public:
  Multirotor(const Airframe& airframe, const Vec3& startPosition, double startYaw,
             double groundZ = 0.0, const IntegratorOptions& options = {});
  ~Multirotor();
  Multirotor(Multirotor&&) noexcept;
  Multirotor& operator=(Multirotor&&) noexcept;
  Multirotor(const Multirotor&) = delete;
  Multirotor& operator=(const Multirotor&) = delete;

  // Accepts a command received at `now` (normally the current time); a command with a NaN or
  // infinite component is rejected, counted and ignored (the previous one stays in force).
  bool command(const Setpoint& setpoint, double now);
  void advance(double dt);
  void kill();

  bool alive() const { return data_.phase != FlightPhase::Dead; }
  // Off the ground: flying, or dead and still falling. Idle and landed vehicles are not.
  bool airborne() const;
  const VehicleState& state() const { return output_; }
  long long rejectedCommands() const { return data_.rejectedCommands; }
  const Airframe& airframe() const { return airframe_; }
  double groundZ() const { return groundZ_; }
  void setGroundZ(double groundZ) { groundZ_ = groundZ; }
  // The attitude loop's current input (for logging and tests).
  const AttitudeCommand& attitudeCommand() const { return data_.input; }
  // Right-hand-side evaluations so far (benchmark).
  long integratorEvaluations() const;

  MultirotorSnapshot snapshot() const;
  void restore(const MultirotorSnapshot& snapshot);

 private:
  void controlTick(double tickTime);
  void integrateTo(double t);
  void fallTo(double t);
  void startSegment();
  void updateOutput();

  Airframe airframe_;
  double groundZ_;
  IntegratorOptions options_;
  TrackingController controller_;
  MultirotorSnapshot data_;
  std::unique_ptr<OdeStepper> stepper_;
  VehicleState output_;
};

}  // namespace coinspect::vehicle
