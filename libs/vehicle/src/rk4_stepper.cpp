// Classical fixed-step RK4: the reference the CVODE integration is measured against.
#include "coinspect/core/error.h"
#include "ode_stepper.h"

namespace coinspect::vehicle {
namespace {

class Rk4Stepper : public OdeStepper {
 public:
  explicit Rk4Stepper(double step) : step_(step) { COINSPECT_ASSERT(step > 0.0); }

  void reset(double t0, const StateVector& y0, double tStop) override {
    gridTime_ = t0;
    gridState_ = y0;
    tStop_ = tStop;
  }

  void advanceTo(const RigidBodyModel& model, double t, StateVector& y) override {
    // Whole steps on the grid t0 + n h (never beyond t), then one uncommitted partial step to t,
    // so that the grid does not depend on the output times.
    while (gridTime_ + step_ <= t + 1e-12) {
      gridState_ = stepFrom(model, gridState_, step_);
      gridTime_ += step_;
    }
    y = (t - gridTime_ > 1e-12) ? stepFrom(model, gridState_, t - gridTime_) : gridState_;
  }

  long evaluations() const override { return evaluations_; }

 private:
  StateVector stepFrom(const RigidBodyModel& model, const StateVector& y, double h) {
    StateVector k1, k2, k3, k4, tmp;
    model.derivative(y.data(), k1.data());
    for (int i = 0; i < kStateSize; ++i)
      tmp[i] = y[i] + 0.5 * h * k1[i];
    model.derivative(tmp.data(), k2.data());
    for (int i = 0; i < kStateSize; ++i)
      tmp[i] = y[i] + 0.5 * h * k2[i];
    model.derivative(tmp.data(), k3.data());
    for (int i = 0; i < kStateSize; ++i)
      tmp[i] = y[i] + h * k3[i];
    model.derivative(tmp.data(), k4.data());
    evaluations_ += 4;
    StateVector out;
    for (int i = 0; i < kStateSize; ++i) {
      out[i] = y[i] + h / 6.0 * (k1[i] + 2.0 * k2[i] + 2.0 * k3[i] + k4[i]);
    }
    return out;
  }

  double step_;
  double gridTime_ = 0.0;
  double tStop_ = 0.0;
  StateVector gridState_{};
  long evaluations_ = 0;
};

}  // namespace

std::unique_ptr<OdeStepper> makeRk4Stepper(const IntegratorOptions& options) {
  return std::make_unique<Rk4Stepper>(options.rk4Step);
}

}  // namespace coinspect::vehicle
