#include "models/hopper/flow_pattern.hpp"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_min.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <memory>
#include <numbers>
#include <stdexcept>

#include "models/hopper/enstad_flow_factor.hpp"
#include "models/numerics/gsl_errors_as_status.hpp"
#include "models/units/angle.hpp"

namespace feedflow {
namespace {

std::string degrees(double rad) {
  char text[32];
  std::snprintf(text, sizeof text, "%.1f deg", rad / kDegree);
  return text;
}

double enstad_ff(double theta, void* params) {
  const auto* p = static_cast<const std::array<double, 3>*>(params);
  return enstad_flow_factor((*p)[0] == 0.0 ? FlowGeometry::plane : FlowGeometry::conical, theta,
                            (*p)[1], (*p)[2]);
}

struct FlowFactorMinimum {
  double semi_angle;
  double flow_factor;
};

// Minimum of the closed-form ff over (0, theta_max]: a coarse scan, then GSL's Brent minimiser
// around the lowest grid point (ff(theta) is smooth with a single interior minimum).
FlowFactorMinimum minimum_flow_factor(FlowGeometry g, double theta_max, double delta,
                                      double phi_w) {
  std::array<double, 3> params{static_cast<double>(geometry_index(g)), delta, phi_w};
  constexpr int kGrid = 16;
  const double lo = 0.5 * kDegree;
  double best_theta = lo, best = enstad_ff(lo, &params);
  std::array<double, kGrid + 1> thetas{}, values{};
  for (int i = 0; i <= kGrid; ++i) {
    thetas[i] = lo + (theta_max - lo) * i / kGrid;
    values[i] = enstad_ff(thetas[i], &params);
    if (values[i] < best) best = values[i], best_theta = thetas[i];
  }
  const auto i = static_cast<int>(std::find(thetas.begin(), thetas.end(), best_theta) -
                                  thetas.begin());
  if (i == 0 || i >= kGrid) return {best_theta, best};  // minimum at an end of the range
  const GslErrorsAsStatus quiet;
  std::unique_ptr<gsl_min_fminimizer, decltype(&gsl_min_fminimizer_free)> m(
      gsl_min_fminimizer_alloc(gsl_min_fminimizer_brent), &gsl_min_fminimizer_free);
  gsl_function f{enstad_ff, &params};
  if (gsl_min_fminimizer_set_with_values(m.get(), &f, thetas[i], values[i], thetas[i - 1],
                                         values[i - 1], thetas[i + 1], values[i + 1]) !=
      GSL_SUCCESS)
    return {best_theta, best};
  for (int iter = 0; iter < 50; ++iter) {
    if (gsl_min_fminimizer_iterate(m.get()) != GSL_SUCCESS) break;
    if (gsl_min_test_interval(gsl_min_fminimizer_x_lower(m.get()),
                              gsl_min_fminimizer_x_upper(m.get()), 1e-4, 0.0) == GSL_SUCCESS)
      break;
  }
  if (gsl_min_fminimizer_f_minimum(m.get()) > best) return {best_theta, best};
  return {gsl_min_fminimizer_x_minimum(m.get()), gsl_min_fminimizer_f_minimum(m.get())};
}

}  // namespace

const char* to_string(FlowPattern p) { return p == FlowPattern::mass ? "mass" : "funnel"; }

double conical_mass_flow_limit(double delta, double phi_w) {
  const double beta = wall_stress_angle(delta, phi_w);
  const double sd = std::sin(delta);
  const double arg = (1.0 - sd) / (2.0 * sd);
  if (arg > 1.0)
    throw std::invalid_argument("Arnold-McLean boundary needs delta >= 19.47 deg, got " +
                                degrees(delta));
  return 0.5 * std::numbers::pi - 0.5 * std::acos(arg) - beta;
}

MassFlowLimit wedge_mass_flow_limit(double delta, double phi_w) {
  const double c = conical_mass_flow_limit(delta, phi_w);
  return {c + 10.0 * kDegree, c + 8.0 * kDegree, c + 12.0 * kDegree,
          "interim wedge rule: conical Arnold-McLean limit + 8...12 deg"};
}

MassFlowLimit mass_flow_limit(FlowGeometry g, double delta, double phi_w) {
  if (g == FlowGeometry::plane) return wedge_mass_flow_limit(delta, phi_w);
  const double c = conical_mass_flow_limit(delta, phi_w);
  // The RSF's last admissible root lies up to 0.2 deg beyond the fit (section 1.2).
  return {c, c - 0.1 * kDegree, c + 0.2 * kDegree, "Arnold-McLean conical boundary"};
}

FlowPatternVerdict classify_flow_pattern(FlowGeometry g, double theta, double delta,
                                         double phi_w, double design_margin) {
  if (!(theta > 0.0 && theta < 0.5 * std::numbers::pi))
    throw std::invalid_argument("hopper semi-angle must lie in (0, 90) deg");
  if (!(design_margin >= 0.0)) throw std::invalid_argument("design margin must be >= 0");
  FlowPatternVerdict v{};
  v.limit = mass_flow_limit(g, delta, phi_w);
  v.margin = v.limit.nominal - theta;
  v.pattern = v.margin >= 0.0 ? FlowPattern::mass : FlowPattern::funnel;
  v.flow_factor_ratio = 0.0;
  if (v.pattern == FlowPattern::funnel) {
    v.near_boundary = theta - v.limit.high < design_margin;
    v.reason = "semi-angle " + degrees(theta) + " is " + degrees(-v.margin) +
               " beyond the mass-flow limit " + degrees(v.limit.nominal) + " (" + v.limit.model +
               ")";
    return v;
  }
  const auto minimum = minimum_flow_factor(g, v.limit.nominal, delta, phi_w);
  v.flow_factor_ratio = enstad_flow_factor(g, theta, delta, phi_w) / minimum.flow_factor;
  const bool within_margin = theta > v.limit.low - design_margin;
  // ff also rises towards steep walls (small theta); only its rise towards the boundary counts.
  const bool steep_ff = v.flow_factor_ratio > 1.5 && theta > minimum.semi_angle;
  v.near_boundary = within_margin || steep_ff;
  v.reason = "semi-angle " + degrees(theta) + " is " + degrees(v.margin) +
             " inside the mass-flow limit " + degrees(v.limit.nominal) + " (" + v.limit.model +
             ")";
  if (within_margin)
    v.reason += "; near the boundary: within the " + degrees(design_margin) +
                " design margin of the band's low end " + degrees(v.limit.low);
  if (steep_ff) {
    char text[96];
    std::snprintf(text, sizeof text, "; near the boundary: ff is %.2f times its minimum (> 1.5)",
                  v.flow_factor_ratio);
    v.reason += text;
  }
  return v;
}

}  // namespace feedflow
