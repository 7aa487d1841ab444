#include "models/hypoplastic/at_rest_stress_ratio.hpp"

#include <stdexcept>
#include <string>

#include "models/core/errors.hpp"
#include "models/hypoplastic/stress_rate.hpp"
#include "models/numerics/brent_root.hpp"

namespace feedflow {
namespace {

struct Problem {
  const HypoplasticModel* model;
  double p;
  double e;
};

// dT_xx/dT_zz - K for the state sigma_h = K sigma_v at mean pressure p.
double rate_mismatch(double k, const Problem& pr) {
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
  const Problem problem{&model, p, e};
  const auto mismatch = [&problem](double k) { return rate_mismatch(k, problem); };
  if (mismatch(0.02) * mismatch(1.0) > 0.0)
    throw NumericalFailure("at_rest_stress_ratio: no K0 in [0.02, 1] at this state");
  const BrentSearch root = brent_search(mismatch, 0.02, 1.0, {0.0, 1e-12, 200});
  if (!root.converged())
    throw NumericalFailure("at_rest_stress_ratio: Brent's method found no K0 in [0.02, 1] at "
                           "this state (GSL status " + std::to_string(root.status) + ")");
  return root.root;
}

}  // namespace feedflow
