#include "coinspect/vehicle/multirotor.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "coinspect/core/error.h"
#include "ode_stepper.h"
#include "rigid_body.h"

namespace coinspect::vehicle {
namespace {

// Ticks closer than this to the end of an advance() are taken in it (absorbs the rounding of
// sums of dt such as 0.0025 * 20 != 0.05).
constexpr double kTickEpsilon = 1e-9;
// Output times closer than this to the current time are not integrated (CVODE refuses them).
constexpr double kMinInterval = 1e-12;

StateVector toArray(const double (&values)[kStateSize]) {
  StateVector out;
  std::copy(std::begin(values), std::end(values), out.begin());
  return out;
}

}  // namespace

Multirotor::Multirotor(const Airframe& airframe, const Vec3& startPosition, double startYaw,
                       double groundZ, const IntegratorOptions& options)
    : airframe_(airframe), groundZ_(groundZ), options_(options), controller_(airframe) {
  validateAirframe(airframe, "Multirotor");
  if (!startPosition.allFinite() || !std::isfinite(startYaw) || !std::isfinite(groundZ)) {
    throw InputError("Multirotor", "airframe '" + airframe.name + "'",
                     "start pose and ground height must be finite");
  }
  stepper_ =
      options.method == Integrator::Cvode ? makeCvodeStepper(options) : makeRk4Stepper(options);
  for (int i = 0; i < 3; ++i)
    data_.state[kPx + i] = startPosition[i];
  data_.state[kYaw] = startYaw;
  updateOutput();
}

Multirotor::~Multirotor() = default;
Multirotor::Multirotor(Multirotor&&) noexcept = default;
Multirotor& Multirotor::operator=(Multirotor&&) noexcept = default;

bool Multirotor::command(const Setpoint& setpoint, double now) {
  if (!isFinite(setpoint) || !std::isfinite(now)) {
    ++data_.rejectedCommands;
    return false;
  }
  controller_.setCommand(setpoint, now);
  return true;
}

bool Multirotor::airborne() const {
  switch (data_.phase) {
    case FlightPhase::Idle:
      return false;
    case FlightPhase::Flying:
      return !data_.grounded;
    case FlightPhase::Dead:
      return !data_.resting;
  }
  return false;
}

long Multirotor::integratorEvaluations() const {
  return stepper_->evaluations();
}

void Multirotor::advance(double dt) {
  COINSPECT_ASSERT(std::isfinite(dt) && dt >= 0.0);
  const double target = data_.time + dt;
  for (;;) {
    const double tick = static_cast<double>(data_.nextTick) * kControlPeriod;
    if (tick > target + kTickEpsilon) break;
    if (tick > data_.time) integrateTo(tick);
    data_.time = tick;
    ++data_.nextTick;
    updateOutput();
    controlTick(tick);
  }
  if (target > data_.time) integrateTo(target);
  updateOutput();
}

void Multirotor::integrateTo(double t) {
  if (t - data_.time < kMinInterval) {
    data_.time = std::max(data_.time, t);
    return;
  }
  if (data_.phase == FlightPhase::Dead) {
    fallTo(t);
    return;
  }
  if (data_.phase == FlightPhase::Idle) {
    data_.time = t;
    return;
  }
  const RigidBodyModel model{&airframe_, data_.input, data_.grounded};
  StateVector y;
  try {
    stepper_->advanceTo(model, t, y);
  } catch (const std::runtime_error& error) {
    throw std::runtime_error("airframe '" + airframe_.name + "': " + error.what() +
                             "; its time constants (attitude_time_constant, mass / "
                             "drag_coefficient) may be too small for the integrator");
  }
  std::copy(y.begin(), y.end(), data_.state);
  data_.time = t;
  if (!data_.grounded && data_.state[kPz] < groundZ_) {
    // Ground contact: no bounce; if the thrust cannot lift the vehicle it rests on the ground.
    data_.state[kPz] = groundZ_;
    data_.state[kVz] = 0.0;
    const Vec3 up = thrustDirection(data_.state[kRoll], data_.state[kPitch], data_.state[kYaw]);
    if (data_.input.thrust * up.z() <= airframe_.mass * kGravity) {
      data_.grounded = true;
      data_.state[kVx] = data_.state[kVy] = 0.0;
    }
    startSegment();
  }
}

void Multirotor::fallTo(double t) {
  data_.time = t;
  if (data_.resting) return;
  const double tau = t - data_.killTime;
  const Vec3& p0 = data_.killPosition;
  const Vec3& v0 = data_.killVelocity;
  Vec3 p = p0 + v0 * tau - 0.5 * kGravity * tau * tau * Vec3::UnitZ();
  Vec3 v = v0 - kGravity * tau * Vec3::UnitZ();
  if (p.z() <= groundZ_) {
    const double drop = std::max(0.0, p0.z() - groundZ_);
    const double landing = (v0.z() + std::sqrt(v0.z() * v0.z() + 2.0 * kGravity * drop)) / kGravity;
    p = p0 + v0 * landing;
    p.z() = groundZ_;
    v.setZero();
    data_.resting = true;
  }
  for (int i = 0; i < 3; ++i) {
    data_.state[kPx + i] = p[i];
    data_.state[kVx + i] = v[i];
  }
}

void Multirotor::controlTick(double tickTime) {
  if (data_.phase == FlightPhase::Dead) return;
  const std::optional<AttitudeCommand> command = controller_.tick(tickTime, output_);
  if (!command) return;
  data_.phase = FlightPhase::Flying;
  data_.input = *command;
  if (data_.grounded) {
    const Vec3 up = thrustDirection(data_.state[kRoll], data_.state[kPitch], data_.state[kYaw]);
    if (data_.input.thrust * up.z() > airframe_.mass * kGravity) data_.grounded = false;
  }
  startSegment();
}

void Multirotor::startSegment() {
  data_.segmentTime = data_.time;
  std::copy(std::begin(data_.state), std::end(data_.state), data_.segmentState);
  stepper_->reset(data_.time, toArray(data_.state),
                  static_cast<double>(data_.nextTick) * kControlPeriod);
}

void Multirotor::kill() {
  if (data_.phase == FlightPhase::Dead) return;
  data_.resting = !airborne();
  data_.phase = FlightPhase::Dead;
  data_.input = AttitudeCommand{};
  data_.killTime = data_.time;
  data_.state[kYawRate] = 0.0;
  for (int i = 0; i < 3; ++i) {
    data_.killPosition[i] = data_.state[kPx + i];
    data_.killVelocity[i] = data_.resting ? 0.0 : data_.state[kVx + i];
  }
  if (data_.resting) {
    for (int i = 0; i < 3; ++i)
      data_.state[kVx + i] = 0.0;
  }
  updateOutput();
}

void Multirotor::updateOutput() {
  const double* y = data_.state;
  output_.position = Vec3(y[kPx], y[kPy], y[kPz]);
  output_.velocity = Vec3(y[kVx], y[kVy], y[kVz]);
  output_.roll = y[kRoll];
  output_.pitch = y[kPitch];
  output_.yaw = wrapAngle(y[kYaw]);
  output_.time = data_.time;
  output_.angularVelocity.setZero();
  if (data_.phase == FlightPhase::Flying) {
    const RigidBodyModel model{&airframe_, data_.input, data_.grounded};
    StateVector dy;
    model.derivative(y, dy.data());
    output_.angularVelocity = bodyRates(y[kRoll], y[kPitch], dy[kRoll], dy[kPitch], y[kYawRate]);
  }
}

MultirotorSnapshot Multirotor::snapshot() const {
  MultirotorSnapshot out = data_;
  out.controller = controller_.memory();
  return out;
}

void Multirotor::restore(const MultirotorSnapshot& snapshot) {
  data_ = snapshot;
  controller_.setMemory(snapshot.controller);
  // Restart the integrator where the original was last restarted: it then takes the same steps.
  if (data_.phase == FlightPhase::Flying) {
    stepper_->reset(data_.segmentTime, toArray(data_.segmentState),
                    static_cast<double>(data_.nextTick) * kControlPeriod);
  }
  updateOutput();
}

}  // namespace coinspect::vehicle
