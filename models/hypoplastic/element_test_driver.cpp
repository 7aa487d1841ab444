#include "models/hypoplastic/element_test_driver.hpp"

#include <cvode/cvode.h>
#include <nvector/nvector_serial.h>
#include <sundials/sundials_context.h>
#include <sunlinsol/sunlinsol_dense.h>
#include <sunmatrix/sunmatrix_dense.h>

#include <cmath>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>

#include "models/core/errors.hpp"
#include "models/hypoplastic/void_ratio_evolution.hpp"

namespace feedflow {
namespace {

constexpr int kSize = 13;  // stress (6), void ratio, strain (6)

MaterialPointState state_of(const double* y) {
  MaterialPointState s;
  for (int k = 0; k < 6; ++k) {
    s.stress(kComponentRow[k], kComponentColumn[k]) = y[k];
    s.stress(kComponentColumn[k], kComponentRow[k]) = y[k];
  }
  s.void_ratio = y[6];
  return s;
}

ElementTestSample sample_of(const double* y, double time, int stage) {
  ElementTestSample out;
  const MaterialPointState s = state_of(y);
  out.time = time;
  out.stage = stage;
  out.stress = s.stress;
  out.void_ratio = s.void_ratio;
  for (int k = 0; k < 6; ++k) {
    out.strain(kComponentRow[k], kComponentColumn[k]) = y[7 + k];
    out.strain(kComponentColumn[k], kComponentRow[k]) = y[7 + k];
  }
  return out;
}

struct StageContext {
  MixedControlSolver* solver;
  const LoadingStage* stage;
  std::optional<std::string> failure;
};

int right_hand_side(sunrealtype, N_Vector y, N_Vector ydot, void* user) {
  auto& c = *static_cast<StageContext*>(user);
  const double* in = N_VGetArrayPointer(y);
  double* out = N_VGetArrayPointer(ydot);
  const MaterialPointState s = state_of(in);
  if (!(s.void_ratio > 0.0)) return 1;  // recoverable: CVODE retries with a smaller step
  try {
    const ElementRates r = c.solver->solve(s);
    const ElementControl& control = c.stage->control;
    for (int k = 0; k < 6; ++k) {
      // Stress-controlled components get their prescribed rate exactly: the solve's residual
      // noise would otherwise enter CVODE's difference-quotient Jacobian and let them drift.
      out[k] = control.control[k] == ComponentControl::stress
                   ? control.rate[k]
                   : r.stress_rate(kComponentRow[k], kComponentColumn[k]);
      out[7 + k] = r.stretching(kComponentRow[k], kComponentColumn[k]);
    }
    out[6] = void_ratio_rate(s.void_ratio, r.stretching.trace());
  } catch (const NumericalFailure& e) {
    c.failure = e.what();
    return 1;
  }
  return 0;
}

int stop_condition(sunrealtype, N_Vector y, sunrealtype* g, void* user) {
  const auto& c = *static_cast<const StageContext*>(user);
  g[0] = N_VGetArrayPointer(y)[c.stage->stop_component] - c.stage->stop_stress;
  return 0;
}

// RAII owners of the SUNDIALS objects.
struct Sundials {
  SUNContext context = nullptr;
  N_Vector y = nullptr;
  N_Vector absolute = nullptr;
  SUNMatrix matrix = nullptr;
  SUNLinearSolver linear = nullptr;
  void* cvode = nullptr;
  Sundials() {
    if (SUNContext_Create(nullptr, &context) != 0) throw NumericalFailure("CVODE: no context");
    y = N_VNew_Serial(kSize, context);
    absolute = N_VNew_Serial(kSize, context);
    matrix = SUNDenseMatrix(kSize, kSize, context);
    linear = SUNLinSol_Dense(y, matrix, context);
    cvode = CVodeCreate(CV_BDF, context);
    if (!y || !absolute || !matrix || !linear || !cvode)
      throw NumericalFailure("CVODE: could not allocate the element-test solver");
  }
  ~Sundials() {
    if (cvode) CVodeFree(&cvode);
    if (linear) SUNLinSolFree(linear);
    if (matrix) SUNMatDestroy(matrix);
    if (absolute) N_VDestroy(absolute);
    if (y) N_VDestroy(y);
    if (context) SUNContext_Free(&context);
  }
  Sundials(const Sundials&) = delete;
  Sundials& operator=(const Sundials&) = delete;
};

void check(int flag, const char* call, const StageContext& c) {
  if (flag >= 0) return;
  std::string message = std::string("element test: CVODE ") + call + " failed (flag " +
                        std::to_string(flag) + ")";
  if (c.failure) message += ": " + *c.failure;
  throw NumericalFailure(message);
}

void validate(const LoadingStage& s, std::size_t index) {
  const std::string where = "element test stage " + std::to_string(index) + ": ";
  if (!(s.duration > 0.0)) throw std::invalid_argument(where + "duration must be > 0");
  if (s.samples < 1) throw std::invalid_argument(where + "needs at least one sample");
  if (s.stop_component < -1 || s.stop_component > 5)
    throw std::invalid_argument(where + "stop component must be -1 (none) or 0..5");
}

}  // namespace

std::vector<ElementTestSample> run_element_test(const HypoplasticModel& model,
                                                const MaterialPointState& initial,
                                                std::span<const LoadingStage> stages,
                                                const ElementTestTolerances& tol) {
  if (!(initial.void_ratio > 0.0) || !initial.stress.allFinite())
    throw std::invalid_argument("element test: the initial state needs e > 0 and a finite stress");
  for (std::size_t i = 0; i < stages.size(); ++i) validate(stages[i], i);

  Sundials sun;
  double* y = N_VGetArrayPointer(sun.y);
  double* atol = N_VGetArrayPointer(sun.absolute);
  for (int k = 0; k < 6; ++k) {
    y[k] = initial.stress(kComponentRow[k], kComponentColumn[k]);
    y[7 + k] = 0.0;
    atol[k] = tol.stress_absolute;
    atol[7 + k] = tol.strain_absolute;
  }
  y[6] = initial.void_ratio;
  atol[6] = tol.void_ratio_absolute;

  std::vector<ElementTestSample> path{sample_of(y, 0.0, 0)};
  double time = 0.0;
  bool initialised = false;
  for (std::size_t i = 0; i < stages.size(); ++i) {
    const LoadingStage& stage = stages[i];
    MixedControlSolver solver(model, stage.control);
    StageContext context{&solver, &stage, std::nullopt};
    // The right-hand side jumps between stages: restart the integrator at each one.
    if (!initialised) {
      check(CVodeInit(sun.cvode, right_hand_side, time, sun.y), "CVodeInit", context);
      check(CVodeSVtolerances(sun.cvode, tol.relative, sun.absolute), "CVodeSVtolerances", context);
      check(CVodeSetLinearSolver(sun.cvode, sun.linear, sun.matrix), "CVodeSetLinearSolver",
            context);
      initialised = true;
    } else {
      check(CVodeReInit(sun.cvode, time, sun.y), "CVodeReInit", context);
    }
    check(CVodeSetUserData(sun.cvode, &context), "CVodeSetUserData", context);
    check(CVodeSetMaxNumSteps(sun.cvode, tol.max_steps), "CVodeSetMaxNumSteps", context);
    const double end = time + stage.duration;
    check(CVodeSetStopTime(sun.cvode, end), "CVodeSetStopTime", context);
    check(CVodeRootInit(sun.cvode, stage.stop_component >= 0 ? 1 : 0,
                        stage.stop_component >= 0 ? stop_condition : nullptr),
          "CVodeRootInit", context);

    const double start = time;
    for (int s = 1; s <= stage.samples; ++s) {
      const double target = s == stage.samples ? end : start + stage.duration * s / stage.samples;
      sunrealtype reached = time;
      const int flag = CVode(sun.cvode, target, sun.y, &reached, CV_NORMAL);
      check(flag, "CVode", context);
      time = reached;
      path.push_back(sample_of(y, time, static_cast<int>(i)));
      if (flag == CV_ROOT_RETURN) break;
    }
  }
  return path;
}

}  // namespace feedflow
