#include "fullsim/dem/time_step_choice.hpp"

#include <cmath>
#include <cstdio>

#include "models/core/errors.hpp"
#include "models/core/printf_format.hpp"

namespace feedflow {
namespace {

constexpr double kPrintedPrecision = 5e-4;  // half a unit in the 4th significant digit, relative

}  // namespace

TimeStepChoice choose_time_step(const StableTimeStep& stable, double requested, bool force) {
  TimeStepChoice c;
  c.stable = stable.value;
  if (!(requested > 0.0)) {
    c.value = stable.value;
    c.justification = "stable step: " + stable.justification;
    return c;
  }
  // The stable step as printed (4 significant digits) and typed back is the stable step.
  if (std::abs(requested - stable.value) <= kPrintedPrecision * stable.value) {
    c.value = stable.value;
    c.justification = format("user step %.4g s, the stable step %.4g s as printed", requested, stable.value);
    return c;
  }
  c.value = requested;
  if (requested <= stable.value) {
    c.justification = format("user step %.4g s (stable step %.4g s)", requested, stable.value);
    if (requested < 0.5 * stable.value)
      c.warning = format("warning: the user time step %.4g s is below the stable step %.4g s; "
                         "the run is safe but slower than it needs to be",
                         requested, stable.value);
    return c;
  }
  if (!force)
    throw InputError("", "dem.time_step",
                     format("time step %.4g s exceeds the stable step %.4g s (", requested,
                            stable.value) +
                         stable.justification + "); give at most the stable step");
  c.justification = format("user step %.4g s FORCED above the stable step %.4g s", requested,
                           stable.value);
  c.warning = "warning: " + c.justification + "; the blow-up guard watches the run";
  return c;
}

}  // namespace feedflow
