// SUNDIALS CVODE (Adams-Moulton with fixed-point iteration: the model is not stiff). One solver
// per vehicle lives as long as the vehicle; each segment only calls CVodeReInit.
#include <cvode/cvode.h>
#include <nvector/nvector_serial.h>
#include <sunnonlinsol/sunnonlinsol_fixedpoint.h>

#include <cstdlib>
#include <stdexcept>
#include <string>

#include "coinspect/core/error.h"
#include "ode_stepper.h"

namespace coinspect::vehicle {
namespace {

struct CallbackData {
  const RigidBodyModel* model = nullptr;
  long evaluations = 0;
};

int rightHandSide(sunrealtype, N_Vector y, N_Vector dy, void* userData) {
  auto* data = static_cast<CallbackData*>(userData);
  data->model->derivative(N_VGetArrayPointer(y), N_VGetArrayPointer(dy));
  ++data->evaluations;
  return 0;
}

void check(int flag, const char* call) {
  if (flag < 0) failAssertion((std::string(call) + " failed").c_str(), __FILE__, __LINE__);
}

class CvodeStepper : public OdeStepper {
 public:
  explicit CvodeStepper(const IntegratorOptions& options) {
    check(SUNContext_Create(nullptr, &context_), "SUNContext_Create");
    y_ = N_VNew_Serial(kStateSize, context_);
    N_VConst(0.0, y_);
    memory_ = CVodeCreate(CV_ADAMS, context_);
    COINSPECT_ASSERT(memory_ != nullptr);
    check(CVodeInit(memory_, rightHandSide, 0.0, y_), "CVodeInit");
    check(CVodeSStolerances(memory_, options.relativeTolerance, options.absoluteTolerance),
          "CVodeSStolerances");
    solver_ = SUNNonlinSol_FixedPoint(y_, 0, context_);
    check(CVodeSetNonlinearSolver(memory_, solver_), "CVodeSetNonlinearSolver");
    check(CVodeSetUserData(memory_, &data_), "CVodeSetUserData");
    // A fixed first step makes the step sequence independent of the requested output times.
    check(CVodeSetInitStep(memory_, options.cvodeInitialStep), "CVodeSetInitStep");
    check(CVodeSetMaxNumSteps(memory_, 100000), "CVodeSetMaxNumSteps");
  }

  ~CvodeStepper() override {
    CVodeFree(&memory_);
    SUNNonlinSolFree(solver_);
    N_VDestroy(y_);
    SUNContext_Free(&context_);
  }

  CvodeStepper(const CvodeStepper&) = delete;
  CvodeStepper& operator=(const CvodeStepper&) = delete;

  void reset(double t0, const StateVector& y0, double tStop) override {
    std::copy(y0.begin(), y0.end(), N_VGetArrayPointer(y_));
    check(CVodeReInit(memory_, t0, y_), "CVodeReInit");
    check(CVodeSetStopTime(memory_, tStop), "CVodeSetStopTime");
    t0_ = t0;
  }

  void advanceTo(const RigidBodyModel& model, double t, StateVector& y) override {
    data_.model = &model;
    sunrealtype reached = t0_;
    // Not an assertion: airframe values (a time constant far below the step) can make the model
    // too stiff for this non-stiff method, and the caller names the airframe.
    const int flag = CVode(memory_, t, y_, &reached, CV_NORMAL);
    if (flag < 0) {
      // CVodeGetReturnFlagName returns a malloc'ed name that the caller frees.
      char* name = CVodeGetReturnFlagName(flag);
      const std::string flagName = name != nullptr ? name : std::to_string(flag);
      std::free(name);
      throw std::runtime_error("CVODE could not integrate from t = " + std::to_string(reached) +
                               " s to " + std::to_string(t) + " s (" + flagName + ")");
    }
    const double* values = N_VGetArrayPointer(y_);
    std::copy(values, values + kStateSize, y.begin());
  }

  long evaluations() const override { return data_.evaluations; }

 private:
  SUNContext context_ = nullptr;
  N_Vector y_ = nullptr;
  void* memory_ = nullptr;
  SUNNonlinearSolver solver_ = nullptr;
  CallbackData data_;
  double t0_ = 0.0;
};

}  // namespace

std::unique_ptr<OdeStepper> makeCvodeStepper(const IntegratorOptions& options) {
  return std::make_unique<CvodeStepper>(options);
}

}  // namespace coinspect::vehicle
