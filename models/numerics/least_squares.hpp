#pragma once
// Nonlinear least squares by GSL's trust-region Levenberg-Marquardt (gsl_multifit_nlinear,
// finite-difference Jacobian): the parameters p minimising sum_i r_i(p)^2, their covariance
// (s^2 (J^T J)^-1, s^2 = the residual sum over n - p) and standard errors. What calibration fits
// with.
//
//   const LeastSquaresFit fit = least_squares(
//       [&](std::span<const double> p, std::span<double> r) { ... r[i] = model(x[i], p) - y[i]; },
//       {1.0, 1.5}, n);
//   fit.parameters; fit.standard_errors; fit.rms;
#include <functional>
#include <span>
#include <vector>

namespace feedflow {

struct LeastSquaresFit {
  std::vector<double> parameters;
  std::vector<double> standard_errors;  // per parameter; +infinity where n <= p or J is singular
  double rms = 0.0;                     // sqrt(sum r^2 / n) at the fit
  int iterations = 0;
};

// `residuals(p, r)` fills r (n entries) for parameters p; `start`: the first guess (p entries).
// Throws NumericalFailure when the solver fails or a residual is not finite at the fit, and
// std::invalid_argument for n < p or no parameters.
LeastSquaresFit least_squares(const std::function<void(std::span<const double>, std::span<double>)>& residuals,
                              std::vector<double> start, std::size_t n);

}  // namespace feedflow
