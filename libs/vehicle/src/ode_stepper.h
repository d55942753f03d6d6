// Integrators of the rigid-body model between two events (private to the library).
//
// A segment starts at reset(t0, y0, tStop) - a control tick, or a ground contact - and the input
// is constant inside it. advanceTo() returns the state at any t in (t0, tStop]. The internal steps
// never depend on which output times are asked for (fixed first step, outputs interpolated), so
// restoring a snapshot (reset at the same segment start) reproduces a run bit for bit.
#pragma once

#include <memory>

#include "coinspect/vehicle/multirotor.h"
#include "rigid_body.h"

namespace coinspect::vehicle {

class OdeStepper {
 public:
  virtual ~OdeStepper() = default;
  virtual void reset(double t0, const StateVector& y0, double tStop) = 0;
  virtual void advanceTo(const RigidBodyModel& model, double t, StateVector& y) = 0;
  // Right-hand-side evaluations since construction (for the benchmark).
  virtual long evaluations() const = 0;
};

std::unique_ptr<OdeStepper> makeCvodeStepper(const IntegratorOptions& options);
std::unique_ptr<OdeStepper> makeRk4Stepper(const IntegratorOptions& options);

}  // namespace coinspect::vehicle
