// The integrator behind Multirotor, tested on its own: a model too stiff for its non-stiff
// method is reported as an exception, never an abort. Airframe files cannot reach this any more
// (time constants >= 0.01 s, airframe_test.cpp); the exception is the guard for what validation
// does not foresee.
#include <gtest/gtest.h>

#include <stdexcept>

#include "../src/ode_stepper.h"
#include "coinspect/testing/input_errors.h"

namespace coinspect::vehicle {
namespace {

TEST(CvodeStepper, AModelTooStiffForItThrowsNamingTheTimes) {
  Airframe airframe;                     // not validated: 1e-7 s would be refused
  airframe.attitudeTimeConstant = 1e-7;  // made a 5 s mission abort inside CVODE (2026-12-08)
  RigidBodyModel model{&airframe, AttitudeCommand{0.3, -0.2, 0.5, 20.0}, false};
  const auto stepper = makeCvodeStepper(IntegratorOptions{});
  StateVector state{};
  state[kPz] = 5.0;
  stepper->reset(0.0, state, 1.0);
  std::string message;
  try {
    stepper->advanceTo(model, 1.0, state);
  } catch (const std::runtime_error& error) {
    message = error.what();
  }
  EXPECT_MENTIONS(message, "CVODE could not integrate");
  EXPECT_MENTIONS(message, "to 1.000000 s");

  // The same command with the shipped time constant integrates.
  airframe.attitudeTimeConstant = 0.1;
  const auto sane = makeCvodeStepper(IntegratorOptions{});
  sane->reset(0.0, state, 1.0);
  EXPECT_NO_THROW(sane->advanceTo(model, 1.0, state));
}

}  // namespace
}  // namespace coinspect::vehicle
