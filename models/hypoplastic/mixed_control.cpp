#include "models/hypoplastic/mixed_control.hpp"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_multiroots.h>

#include <cmath>
#include <string>
#include <vector>

#include "models/core/errors.hpp"
#include "models/hypoplastic/stress_rate.hpp"

namespace feedflow {

struct MixedControlSolver::Workspace {
  const HypoplasticModel* model;
  ElementControl control;
  std::vector<int> unknown;  // stress-controlled components
  Tensor3 known_stretching = Tensor3::Zero();
  // Per solve:
  MaterialPointState state;
  RateTerms terms;
  Tensor3 spin_terms = Tensor3::Zero();
  gsl_multiroot_fdfsolver* solver = nullptr;
  gsl_vector* guess = nullptr;
};

namespace {

using Workspace = MixedControlSolver::Workspace;

void set_component(Tensor3& t, int k, double value) {
  t(kComponentRow[k], kComponentColumn[k]) = value;
  t(kComponentColumn[k], kComponentRow[k]) = value;
}
double weight(int k) { return k < 3 ? 1.0 : 2.0; }  // in D:D and That:D

Tensor3 stretching_of(const Workspace& w, const gsl_vector* x) {
  Tensor3 d = w.known_stretching;
  for (std::size_t i = 0; i < w.unknown.size(); ++i) set_component(d, w.unknown[i], gsl_vector_get(x, i));
  return d;
}

int residual(const gsl_vector* x, void* params, gsl_vector* f) {
  const auto& w = *static_cast<const Workspace*>(params);
  const Tensor3 rate = stress_rate(w.terms, stretching_of(w, x)) + w.spin_terms;
  for (std::size_t i = 0; i < w.unknown.size(); ++i) {
    const int k = w.unknown[i];
    gsl_vector_set(f, i, rate(kComponentRow[k], kComponentColumn[k]) - w.control.rate[k]);
  }
  return GSL_SUCCESS;
}

int jacobian(const gsl_vector* x, void* params, gsl_matrix* j) {
  const auto& w = *static_cast<const Workspace*>(params);
  const Tensor3 d = stretching_of(w, x);
  const RateTerms& r = w.terms;
  const double norm = tensor_norm(d);
  for (std::size_t a = 0; a < w.unknown.size(); ++a) {
    const int s = w.unknown[a];
    const int si = kComponentRow[s], sj = kComponentColumn[s];
    for (std::size_t b = 0; b < w.unknown.size(); ++b) {
      const int u = w.unknown[b];
      const int ui = kComponentRow[u], uj = kComponentColumn[u];
      double value;
      if (r.near_zero) {
        value = (s < 3 && u < 3 && d.trace() < 0.0) ? r.near_zero_modulus : 0.0;
      } else {
        value = r.stiffness * ((s == u ? r.linear : 0.0) + r.projection * weight(u) *
                                   r.normalized_stress(ui, uj) * r.normalized_stress(si, sj));
        if (norm > 0.0) value += r.nonlinear(si, sj) * weight(u) * d(ui, uj) / norm;
      }
      gsl_matrix_set(j, a, b, value);
    }
  }
  return GSL_SUCCESS;
}

int residual_and_jacobian(const gsl_vector* x, void* params, gsl_vector* f, gsl_matrix* j) {
  residual(x, params, f);
  return jacobian(x, params, j);
}

}  // namespace

MixedControlSolver::MixedControlSolver(const HypoplasticModel& model, const ElementControl& control)
    : w_(std::make_unique<Workspace>()) {
  w_->model = &model;
  w_->control = control;
  for (int k = 0; k < 6; ++k) {
    if (control.control[k] == ComponentControl::stress)
      w_->unknown.push_back(k);
    else
      set_component(w_->known_stretching, k, control.rate[k]);
  }
  if (w_->unknown.size() == 6)
    throw std::invalid_argument("mixed control: at least one strain component must be prescribed");
  if (!w_->unknown.empty()) {
    w_->solver = gsl_multiroot_fdfsolver_alloc(gsl_multiroot_fdfsolver_hybridsj, w_->unknown.size());
    w_->guess = gsl_vector_calloc(w_->unknown.size());
  }
}

MixedControlSolver::~MixedControlSolver() {
  if (w_->solver) gsl_multiroot_fdfsolver_free(w_->solver);
  if (w_->guess) gsl_vector_free(w_->guess);
}

ElementRates MixedControlSolver::solve(const MaterialPointState& state) {
  Workspace& w = *w_;
  w.state = state;
  w.terms = rate_terms(*w.model, state.stress, state.void_ratio);
  w.spin_terms = w.control.spin * state.stress - state.stress * w.control.spin;
  if (!w.unknown.empty()) {
    gsl_multiroot_function_fdf f{&residual, &jacobian, &residual_and_jacobian, w.unknown.size(), &w};
    gsl_multiroot_fdfsolver_set(w.solver, &f, w.guess);
    // Residuals are stress rates; converge to 1e-11 of the stress rate scale.
    const double scale =
        std::max(tensor_norm(stress_rate(w.terms, w.known_stretching)), 1e-300) * 1e-11;
    int status = GSL_CONTINUE;
    for (int iteration = 0; iteration < 100 && status == GSL_CONTINUE; ++iteration) {
      if (gsl_multiroot_test_residual(w.solver->f, scale) == GSL_SUCCESS) {
        status = GSL_SUCCESS;
        break;
      }
      status = gsl_multiroot_fdfsolver_iterate(w.solver);
      if (status == GSL_SUCCESS) status = GSL_CONTINUE;
    }
    if (status != GSL_SUCCESS)
      throw NumericalFailure("element test: the stress-controlled components could not be solved "
                             "(GSL status " + std::to_string(status) + ") at p = " +
                             std::to_string(-state.stress.trace() / 3.0) + " Pa, e = " +
                             std::to_string(state.void_ratio));
    gsl_vector_memcpy(w.guess, w.solver->x);
  }
  ElementRates out;
  out.stretching = w.unknown.empty() ? w.known_stretching : stretching_of(w, w.guess);
  out.stress_rate = stress_rate(w.terms, out.stretching) + w.spin_terms;
  return out;
}

}  // namespace feedflow
