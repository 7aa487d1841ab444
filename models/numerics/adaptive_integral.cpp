#include "models/numerics/adaptive_integral.hpp"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_integration.h>

#include <cmath>
#include <memory>

#include "models/core/errors.hpp"
#include "models/numerics/gsl_errors_as_status.hpp"

namespace feedflow {

double adaptive_integral(const std::function<double(double)>& f, double a, double b, double abs_tol,
                         double rel_tol, const std::string& what) {
  const GslErrorsAsStatus quiet;
  constexpr std::size_t kIntervals = 1000;
  std::unique_ptr<gsl_integration_workspace, decltype(&gsl_integration_workspace_free)> ws(
      gsl_integration_workspace_alloc(kIntervals), &gsl_integration_workspace_free);
  gsl_function fn{
      [](double x, void* p) { return (*static_cast<const std::function<double(double)>*>(p))(x); },
      const_cast<std::function<double(double)>*>(&f)};
  double result = 0.0, error = 0.0;
  const int status =
      gsl_integration_qags(&fn, a, b, abs_tol, rel_tol, kIntervals, ws.get(), &result, &error);
  if (status != GSL_SUCCESS || !std::isfinite(result))
    throw NumericalFailure(what + ": quadrature failed (" + gsl_strerror(status) +
                           ", estimated error " + std::to_string(error) + ")");
  return result;
}

}  // namespace feedflow
