#pragma once
// Jenike's radial stress field of a converging hopper in steady (passive) flow, solved by
// shooting (reduced_models.md section 1.2): sigma = rho_b g r s(theta), with psi(theta) the
// angle from the r-direction to sigma1. From the axis (psi = pi/2, s = s0) to the wall
// (psi_w = pi/2 + beta), GSL's adaptive rk8pd (rtol 1e-9) integrates the two equilibrium
// equations and GSL's Brent solver finds ln s0. The high-fidelity flow factor and a
// regression check on the closed form.
#include <optional>

#include "models/hopper/hopper_geometry.hpp"

namespace feedflow {

struct RadialStressField {
  double axis_stress;  // s0 = sigma / (rho_b g r) on the axis
  double wall_stress;  // s(theta_w) at the wall
  double flow_factor;  // ff = (1 + sin delta) s_w H(theta_w) / (2 sin theta_w)
};

// Shooting residual F(s0) = psi(theta_w; s0) - psi_w. Integrates to the wall (it never stops
// at the first crossing of psi_w). A path that reaches the singular line S = cos 2psi counts as
// F > 0 and one that falls below pi/2 - 0.2 as F < 0; both return psi at the stop minus psi_w.
double radial_field_wall_mismatch(FlowGeometry g, double semi_angle,
                                  double effective_friction_angle, double wall_friction_angle,
                                  double axis_stress);

// The admissible field, or nothing when none exists for s0 in [1e-3, 1/((3+2m) sin delta - 1)]
// (F(s0_min) <= 0: conical funnel flow, the existence limit; or F changes sign only across a
// path stopped by a guard, never through psi(theta_w) = psi_w, seen for delta = 25 deg cones
// beyond the limit; and always for phi_w = delta, where psi_w lies on the singular line).
// Throws NumericalFailure when the integration or root finding fails, std::invalid_argument
// for angles out of range.
std::optional<RadialStressField> solve_radial_stress_field(FlowGeometry g, double semi_angle,
                                                           double effective_friction_angle,
                                                           double wall_friction_angle);

// The semi-angle at which F(s0_min) = 0, beyond which no field exists (Brent's method in
// theta); nothing when fields exist up to 89 deg (plane flow usually).
std::optional<double> radial_field_limit_angle(FlowGeometry g, double effective_friction_angle,
                                               double wall_friction_angle);

// Smallest and largest axis stress searched by the shooting.
inline constexpr double kMinAxisStress = 1e-3;
double max_axis_stress(FlowGeometry g, double effective_friction_angle);

}  // namespace feedflow
