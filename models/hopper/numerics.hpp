#pragma once
// The GSL numerics the hopper models share: Brent root bracketing and adaptive quadrature,
// with GSL errors turned into NumericalFailure instead of GSL's default abort.
#include <functional>
#include <string>

namespace feedflow {

// Root of f in [lo, hi] (f(lo), f(hi) of opposite signs) by GSL's Brent solver, to an interval
// narrower than xtol_abs + xtol_rel |x|. `what` names the computation in the error message.
double brent_root(const std::function<double(double)>& f, double lo, double hi, double xtol_abs,
                  double xtol_rel, const std::string& what);

// Integral of f over [a, b] by GSL's QAGS (adaptive, tolerates integrable end singularities),
// to abs_tol or rel_tol, whichever is looser (an integral near zero needs abs_tol).
double adaptive_integral(const std::function<double(double)>& f, double a, double b,
                         double abs_tol, double rel_tol, const std::string& what);

// While alive, GSL errors are returned as status codes instead of aborting the program.
class GslErrorsAsStatus {
 public:
  GslErrorsAsStatus();
  ~GslErrorsAsStatus();
  GslErrorsAsStatus(const GslErrorsAsStatus&) = delete;
  GslErrorsAsStatus& operator=(const GslErrorsAsStatus&) = delete;

 private:
  void (*previous_)(const char*, const char*, int, int);
};

}  // namespace feedflow
