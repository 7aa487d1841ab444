#pragma once
// The time step of a run: the stable step of models.md 5.1 (stable_time_step(), with its
// safety factor: steps per period of the stiffest spring and fractions of the Rayleigh and
// Hertz times), or a user value. A value below the stable step is allowed with a warning
// (it only costs time); one above it is refused unless forced (the engine's setting; the case
// file has no way to force it). The stable step as printed and typed back (within half a unit of
// its 4th significant digit) is the stable step itself.
#include <string>

#include "models/contact/contact_time_step.hpp"

namespace feedflow {

struct TimeStepChoice {
  double value = 0.0;          // the step used [s]
  double stable = 0.0;         // the stable step [s]
  std::string justification;   // why this value, one line
  std::string warning;         // empty unless the user's value needs a word
};

// requested <= 0: use the stable step. Throws InputError for a requested step above the
// stable one unless `force`.
TimeStepChoice choose_time_step(const StableTimeStep& stable, double requested, bool force);

}  // namespace feedflow
