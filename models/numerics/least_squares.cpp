#include "models/numerics/least_squares.hpp"

#include <gsl/gsl_blas.h>
#include <gsl/gsl_multifit_nlinear.h>

#include <cmath>
#include <limits>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "models/core/errors.hpp"
#include "models/numerics/gsl_errors_as_status.hpp"

namespace feedflow {
namespace {

using Residuals = std::function<void(std::span<const double>, std::span<double>)>;

// GSL hands vectors with strides (a column of the Jacobian for its finite differences): copy
// through contiguous buffers.
int gsl_residuals(const gsl_vector* x, void* data, gsl_vector* f) {
  const auto& residuals = *static_cast<const Residuals*>(data);
  std::vector<double> p(x->size), r(f->size);
  for (std::size_t k = 0; k < x->size; ++k) p[k] = gsl_vector_get(x, k);
  residuals(p, r);
  for (std::size_t i = 0; i < f->size; ++i) {
    if (!std::isfinite(r[i])) return GSL_EBADFUNC;
    gsl_vector_set(f, i, r[i]);
  }
  return GSL_SUCCESS;
}

struct WorkspaceFree {
  void operator()(gsl_multifit_nlinear_workspace* w) const { gsl_multifit_nlinear_free(w); }
};
struct MatrixFree {
  void operator()(gsl_matrix* m) const { gsl_matrix_free(m); }
};

}  // namespace

LeastSquaresFit least_squares(const Residuals& residuals, std::vector<double> start, std::size_t n) {
  const std::size_t p = start.size();
  if (p == 0) throw std::invalid_argument("least squares: no parameters to fit");
  if (n < p) throw std::invalid_argument("least squares: fewer residuals than parameters");
  GslErrorsAsStatus gsl_errors;
  gsl_multifit_nlinear_parameters params = gsl_multifit_nlinear_default_parameters();
  std::unique_ptr<gsl_multifit_nlinear_workspace, WorkspaceFree> w(
      gsl_multifit_nlinear_alloc(gsl_multifit_nlinear_trust, &params, n, p));
  gsl_multifit_nlinear_fdf fdf{};
  fdf.f = &gsl_residuals;
  fdf.df = nullptr;  // finite differences
  fdf.n = n;
  fdf.p = p;
  fdf.params = const_cast<Residuals*>(&residuals);
  gsl_vector_view x0 = gsl_vector_view_array(start.data(), p);
  int status = gsl_multifit_nlinear_init(&x0.vector, &fdf, w.get());
  int info = 0;
  if (status == GSL_SUCCESS)
    status = gsl_multifit_nlinear_driver(200, 1e-10, 1e-10, 0.0, nullptr, nullptr, &info, w.get());
  if (status != GSL_SUCCESS)
    throw NumericalFailure(std::string("least squares: the fit failed (") + gsl_strerror(status) + ")");

  LeastSquaresFit fit;
  const gsl_vector* x = gsl_multifit_nlinear_position(w.get());
  fit.parameters.assign(x->data, x->data + p);
  const gsl_vector* f = gsl_multifit_nlinear_residual(w.get());
  double chi2 = 0.0;
  gsl_blas_ddot(f, f, &chi2);
  fit.rms = std::sqrt(chi2 / static_cast<double>(n));
  fit.iterations = static_cast<int>(gsl_multifit_nlinear_niter(w.get()));
  fit.standard_errors.assign(p, std::numeric_limits<double>::infinity());
  if (n > p) {
    std::unique_ptr<gsl_matrix, MatrixFree> covariance(gsl_matrix_alloc(p, p));
    if (gsl_multifit_nlinear_covar(gsl_multifit_nlinear_jac(w.get()), 0.0, covariance.get()) == GSL_SUCCESS) {
      const double s2 = chi2 / static_cast<double>(n - p);
      for (std::size_t k = 0; k < p; ++k) {
        const double v = s2 * gsl_matrix_get(covariance.get(), k, k);
        if (std::isfinite(v) && v >= 0.0) fit.standard_errors[k] = std::sqrt(v);
      }
    }
  }
  return fit;
}

}  // namespace feedflow
