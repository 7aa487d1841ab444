#include "models/hypoplastic/mixed_control.hpp"

#include <Eigen/LU>
#include <cmath>
#include <stdexcept>
#include <string>

#include "models/core/errors.hpp"
#include "models/hypoplastic/stress_rate.hpp"

namespace feedflow {
namespace {

using Vector6 = Eigen::Matrix<double, 6, 1>;
using SmallMatrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, 6, 6>;
using SmallVector = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, 6, 1>;

constexpr std::array<double, 6> kWeight{1, 1, 1, 2, 2, 2};  // in D:D and That:D

double component(const Tensor3& t, int k) { return t(kComponentRow[k], kComponentColumn[k]); }

Vector6 components(const Tensor3& t) {
  Vector6 v;
  for (int k = 0; k < 6; ++k) v(k) = component(t, k);
  return v;
}

Tensor3 tensor(const Vector6& v) {
  Tensor3 t;
  for (int k = 0; k < 6; ++k) {
    t(kComponentRow[k], kComponentColumn[k]) = v(k);
    t(kComponentColumn[k], kComponentRow[k]) = v(k);
  }
  return t;
}

double weighted_dot(const Vector6& x, const Vector6& y) {
  double sum = 0.0;
  for (int k = 0; k < 6; ++k) sum += kWeight[k] * x(k) * y(k);
  return sum;
}

[[noreturn]] void no_solution(const MaterialPointState& s, const char* why) {
  throw NumericalFailure(std::string("element test: the stress control cannot be met (") + why +
                         ") at p = " + std::to_string(-s.stress.trace() / 3.0) +
                         " Pa, e = " + std::to_string(s.void_ratio));
}

}  // namespace

MixedControlSolver::MixedControlSolver(const HypoplasticModel& model, const ElementControl& control)
    : model_(&model), control_(control) {
  for (int k = 0; k < 6; ++k) {
    if (control.control[k] == ComponentControl::stress) {
      unknown_[unknown_count_++] = k;
    } else {
      known_stretching_(kComponentRow[k], kComponentColumn[k]) = control.rate[k];
      known_stretching_(kComponentColumn[k], kComponentRow[k]) = control.rate[k];
    }
  }
  if (unknown_count_ == 6)
    throw std::invalid_argument("mixed control: at least one strain component must be prescribed");
}

ElementRates MixedControlSolver::solve(const MaterialPointState& state) const {
  const RateTerms r = rate_terms(*model_, state.stress, state.void_ratio);
  const Tensor3 spin_terms = control_.spin * state.stress - state.stress * control_.spin;
  ElementRates out;
  out.stretching = known_stretching_;
  if (unknown_count_ > 0) {
    if (r.near_zero) no_solution(state, "stress near zero");
    const int n = unknown_count_;
    // Linear part restricted to the unknowns: L_su = stiffness (linear d_su + projection w_u That_u That_s).
    SmallMatrix l(n, n);
    SmallVector rhs(n), n_u(n);
    const Tensor3 known_rate = r.stiffness * (r.linear * known_stretching_ +
                                              r.projection *
                                                  r.normalized_stress.cwiseProduct(known_stretching_).sum() *
                                                  r.normalized_stress);
    for (int a = 0; a < n; ++a) {
      const int s = unknown_[a];
      for (int b = 0; b < n; ++b) {
        const int u = unknown_[b];
        l(a, b) = r.stiffness * ((s == u ? r.linear : 0.0) + r.projection * kWeight[u] *
                                     component(r.normalized_stress, u) *
                                     component(r.normalized_stress, s));
      }
      rhs(a) = control_.rate[s] - component(known_rate, s) - component(spin_terms, s);
      n_u(a) = component(r.nonlinear, s);
    }
    const Eigen::PartialPivLU<SmallMatrix> lu(l);
    const SmallVector a_u = lu.solve(rhs), b_u = -lu.solve(n_u);
    Vector6 a = components(known_stretching_), b = Vector6::Zero();
    for (int i = 0; i < n; ++i) {
      a(unknown_[i]) = a_u(i);
      b(unknown_[i]) = b_u(i);
    }
    // s = ||a + b s||: (b.b - 1) s^2 + 2 a.b s + a.a = 0, s >= 0.
    const double bb = weighted_dot(b, b), ab = weighted_dot(a, b), aa = weighted_dot(a, a);
    const double c2 = bb - 1.0;
    double s;
    if (std::abs(c2) < 1e-14) {
      if (!(ab < 0.0)) no_solution(state, "no admissible strain rate");
      s = -aa / (2.0 * ab);
    } else {
      const double discriminant = ab * ab - c2 * aa;
      if (discriminant < 0.0) no_solution(state, "no admissible strain rate");
      const double root = std::sqrt(discriminant);
      const double s1 = (-ab - root) / c2, s2 = (-ab + root) / c2;
      const double low = std::min(s1, s2), high = std::max(s1, s2);
      if (low >= 0.0)
        s = low;
      else if (high >= 0.0)
        s = high;
      else
        no_solution(state, "no admissible strain rate");
    }
    out.stretching = tensor(a + b * s);
  }
  out.stress_rate = stress_rate(r, out.stretching) + spin_terms;
  return out;
}

}  // namespace feedflow
