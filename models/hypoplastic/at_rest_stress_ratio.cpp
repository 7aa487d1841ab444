#include "models/hypoplastic/at_rest_stress_ratio.hpp"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_roots.h>

#include <memory>
#include <stdexcept>

#include "models/core/errors.hpp"
#include "models/hypoplastic/stress_rate.hpp"

namespace feedflow {
namespace {

struct Problem {
  const HypoplasticModel* model;
  double p;
  double e;
};

// dT_xx/dT_zz - K for the state sigma_h = K sigma_v at mean pressure p.
double rate_mismatch(double k, void* params) {
  const auto& pr = *static_cast<const Problem*>(params);
  const double vertical = 3.0 * pr.p / (1.0 + 2.0 * k);
  const Tensor3 stress = Eigen::Vector3d(k * vertical, k * vertical, vertical).asDiagonal();
  Tensor3 d = Tensor3::Zero();
  d(2, 2) = -1.0;
  const Tensor3 rate = stress_rate(*pr.model, -stress, pr.e, d);
  return rate(0, 0) / rate(2, 2) - k;
}

}  // namespace

double at_rest_stress_ratio(const HypoplasticModel& model, double p, double e) {
  if (!(p > 0.0) || !(e > 0.0))
    throw std::invalid_argument("at_rest_stress_ratio: need mean pressure > 0 and void ratio > 0");
  Problem problem{&model, p, e};
  gsl_function f{&rate_mismatch, &problem};
  double low = 0.02, high = 1.0;
  if (rate_mismatch(low, &problem) * rate_mismatch(high, &problem) > 0.0)
    throw NumericalFailure("at_rest_stress_ratio: no K0 in [0.02, 1] at this state");
  std::unique_ptr<gsl_root_fsolver, decltype(&gsl_root_fsolver_free)> solver(
      gsl_root_fsolver_alloc(gsl_root_fsolver_brent), &gsl_root_fsolver_free);
  gsl_root_fsolver_set(solver.get(), &f, low, high);
  for (int i = 0; i < 200; ++i) {
    gsl_root_fsolver_iterate(solver.get());
    low = gsl_root_fsolver_x_lower(solver.get());
    high = gsl_root_fsolver_x_upper(solver.get());
    if (gsl_root_test_interval(low, high, 0.0, 1e-12) == GSL_SUCCESS) break;
  }
  return gsl_root_fsolver_root(solver.get());
}

}  // namespace feedflow
