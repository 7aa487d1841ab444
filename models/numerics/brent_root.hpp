#pragma once
// Roots bracketed in [lo, hi] by GSL's Brent solver: the one iteration loop every model uses.
// GSL errors come back as a status (never GSL's default abort); the caller decides what a
// failure means, or lets brent_root throw NumericalFailure.
#include <functional>
#include <string>

namespace feedflow {

// Stop when the bracket [a, b] is narrower than absolute + relative * min(|a|, |b|)
// (gsl_root_test_interval), or after max_iterations steps.
struct BrentTolerance {
  double absolute = 0.0;
  double relative = 0.0;
  int max_iterations = 200;
};

// Where a search ended: the last estimate of the root and GSL's status: GSL_SUCCESS (0) when
// the bracket met the tolerance, GSL_CONTINUE when the iterations ran out, otherwise the error
// of the failed start (f(lo), f(hi) of one sign: GSL_EINVAL) or step (f not finite: GSL_EBADFUNC).
struct BrentSearch {
  double root = 0.0;
  int status = 0;
  bool converged() const { return status == 0; }
};

// Searches for a root of f in [lo, hi]; never throws for a failed search.
BrentSearch brent_search(const std::function<double(double)>& f, double lo, double hi,
                         const BrentTolerance& tolerance);

// Root of f in [lo, hi] (f(lo), f(hi) of opposite signs) to a bracket narrower than
// xtol_abs + xtol_rel |x|, in at most 200 steps. Throws NumericalFailure "<what>: Brent's method
// did not converge on [lo, hi] (reason)" otherwise.
double brent_root(const std::function<double(double)>& f, double lo, double hi, double xtol_abs,
                  double xtol_rel, const std::string& what);

}  // namespace feedflow
