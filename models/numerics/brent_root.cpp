#include "models/numerics/brent_root.hpp"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_roots.h>

#include <memory>

#include "models/core/errors.hpp"
#include "models/numerics/gsl_errors_as_status.hpp"

namespace feedflow {

BrentSearch brent_search(const std::function<double(double)>& f, double lo, double hi,
                         const BrentTolerance& tolerance) {
  const GslErrorsAsStatus quiet;
  std::unique_ptr<gsl_root_fsolver, decltype(&gsl_root_fsolver_free)> solver(
      gsl_root_fsolver_alloc(gsl_root_fsolver_brent), &gsl_root_fsolver_free);
  gsl_function fn{
      [](double x, void* p) { return (*static_cast<const std::function<double(double)>*>(p))(x); },
      const_cast<std::function<double(double)>*>(&f)};
  int status = gsl_root_fsolver_set(solver.get(), &fn, lo, hi);
  if (status != GSL_SUCCESS) return {gsl_root_fsolver_root(solver.get()), status};
  status = GSL_CONTINUE;
  for (int i = 0; i < tolerance.max_iterations && status == GSL_CONTINUE; ++i) {
    status = gsl_root_fsolver_iterate(solver.get());
    if (status != GSL_SUCCESS) break;
    status = gsl_root_test_interval(gsl_root_fsolver_x_lower(solver.get()),
                                    gsl_root_fsolver_x_upper(solver.get()), tolerance.absolute,
                                    tolerance.relative);
  }
  return {gsl_root_fsolver_root(solver.get()), status};
}

double brent_root(const std::function<double(double)>& f, double lo, double hi, double xtol_abs,
                  double xtol_rel, const std::string& what) {
  const BrentTolerance tolerance{xtol_abs, xtol_rel, 200};
  const BrentSearch search = brent_search(f, lo, hi, tolerance);
  if (search.converged()) return search.root;
  throw NumericalFailure(what + ": Brent's method did not converge on [" + std::to_string(lo) +
                         ", " + std::to_string(hi) + "] (" +
                         (search.status == GSL_CONTINUE
                              ? std::string("200 iterations")
                              : std::string(gsl_strerror(search.status))) +
                         ")");
}

}  // namespace feedflow
