#include "models/hopper/numerics.hpp"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_integration.h>
#include <gsl/gsl_roots.h>

#include <cmath>
#include <memory>

#include "models/core/errors.hpp"

namespace feedflow {
namespace {

double call(double x, void* f) { return (*static_cast<const std::function<double(double)>*>(f))(x); }

}  // namespace

GslErrorsAsStatus::GslErrorsAsStatus() : previous_(gsl_set_error_handler_off()) {}
GslErrorsAsStatus::~GslErrorsAsStatus() { gsl_set_error_handler(previous_); }

double brent_root(const std::function<double(double)>& f, double lo, double hi, double xtol_abs,
                  double xtol_rel, const std::string& what) {
  const GslErrorsAsStatus quiet;
  std::unique_ptr<gsl_root_fsolver, decltype(&gsl_root_fsolver_free)> solver(
      gsl_root_fsolver_alloc(gsl_root_fsolver_brent), &gsl_root_fsolver_free);
  gsl_function fn{call, const_cast<std::function<double(double)>*>(&f)};
  int status = gsl_root_fsolver_set(solver.get(), &fn, lo, hi);
  for (int iter = 0; status == GSL_SUCCESS && iter < 200; ++iter) {
    status = gsl_root_fsolver_iterate(solver.get());
    if (status != GSL_SUCCESS) break;
    const double a = gsl_root_fsolver_x_lower(solver.get());
    const double b = gsl_root_fsolver_x_upper(solver.get());
    if (gsl_root_test_interval(a, b, xtol_abs, xtol_rel) == GSL_SUCCESS)
      return gsl_root_fsolver_root(solver.get());
  }
  throw NumericalFailure(what + ": Brent's method did not converge on [" + std::to_string(lo) +
                         ", " + std::to_string(hi) + "] (" +
                         (status == GSL_SUCCESS ? std::string("200 iterations")
                                                : std::string(gsl_strerror(status))) +
                         ")");
}

double adaptive_integral(const std::function<double(double)>& f, double a, double b,
                         double abs_tol, double rel_tol, const std::string& what) {
  const GslErrorsAsStatus quiet;
  constexpr std::size_t kIntervals = 1000;
  std::unique_ptr<gsl_integration_workspace, decltype(&gsl_integration_workspace_free)> ws(
      gsl_integration_workspace_alloc(kIntervals), &gsl_integration_workspace_free);
  gsl_function fn{call, const_cast<std::function<double(double)>*>(&f)};
  double result = 0.0, error = 0.0;
  const int status =
      gsl_integration_qags(&fn, a, b, abs_tol, rel_tol, kIntervals, ws.get(), &result, &error);
  if (status != GSL_SUCCESS || !std::isfinite(result))
    throw NumericalFailure(what + ": quadrature failed (" + gsl_strerror(status) +
                           ", estimated error " + std::to_string(error) + ")");
  return result;
}

}  // namespace feedflow
