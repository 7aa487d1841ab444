#include "models/material/flow_properties.hpp"

#include <algorithm>

#include "models/units/angle.hpp"
#include "models/units/quantity_format.hpp"

namespace feedflow {
namespace {
constexpr std::string_view kFlowFunctions[] = {"linear", "power_law", "tabulated"};
// Strengths of bulk solids at low stress: up to 1 MPa (a cemented cake) [Pa].
constexpr Range kStrengthRange{0.0, 1e6, true, true};
// Consolidation stresses: up to 1 GPa [Pa].
constexpr Range kStressRange{0.0, 1e9, true, true};
}  // namespace

std::span<const FieldSpec<FlowProperties>> flow_property_fields() {
  using F = FlowProperties;
  constexpr auto opt = Presence::optional;
  static const FieldSpec<F> fields[] = {
      label_field<F>("flow_function", &F::flow_function, kFlowFunctions,
                     "form of the flow function sigma_c(sigma1)", opt),
      number_field<F>("ff_slope", &F::ff_slope, dim::dimensionless, "-", Range::half_open(0.0, 1.0),
                      "linear flow function: slope a of sigma_c = a sigma1 + b", opt),
      number_field<F>("ff_intercept", &F::ff_intercept, dim::pressure, "Pa", kStrengthRange,
                      "linear flow function: intercept b (strength at zero consolidation)", opt),
      number_field<F>("ff_coefficient", &F::ff_coefficient, dim::dimensionless, "-",
                      kStrengthRange,
                      "power-law flow function: a of sigma_c = a sigma1^b, stresses in Pa", opt),
      number_field<F>("ff_exponent", &F::ff_exponent, dim::dimensionless, "-",
                      Range::closed(0.0, 2.0), "power-law flow function: exponent b", opt),
      number_list_field<F>("ff_major_stress", &F::ff_major_stress, dim::pressure, "Pa",
                           kStressRange, "tabulated flow function: major consolidation stresses"),
      number_list_field<F>("ff_strength", &F::ff_strength, dim::pressure, "Pa", kStrengthRange,
                           "tabulated flow function: unconfined yield strengths"),
      number_field<F>("ff_uncertainty", &F::ff_uncertainty, dim::dimensionless, "%",
                      Range::half_open(0.0, 1.0), "relative uncertainty of the flow function", opt),
      number_field<F>("effective_friction_angle", &F::effective_friction_angle, dim::angle, "deg",
                      Range::open(0.0, 90.0 * kDegree),
                      "effective angle of internal friction delta"),
      number_field<F>("effective_friction_uncertainty", &F::effective_friction_uncertainty,
                      dim::angle, "deg", Range::closed(0.0, 15.0 * kDegree), "uncertainty of delta",
                      opt),
      number_field<F>("wall_friction_uncertainty", &F::wall_friction_uncertainty, dim::angle, "deg",
                      Range::closed(0.0, 15.0 * kDegree), "uncertainty of the wall friction angle",
                      opt),
      number_list_field<F>("density_major_stress", &F::density_major_stress, dim::pressure, "Pa",
                           kStressRange, "measured compressibility: major consolidation stresses"),
      number_list_field<F>("density", &F::density, dim::density, "kg/m^3", Range::closed(1.0, 20000.0),
                           "measured compressibility: bulk density at those stresses"),
  };
  return fields;
}

std::vector<FieldProblem> check(const FlowProperties& p) {
  std::vector<FieldProblem> problems;
  if (p.flow_function == "tabulated") {
    if (p.ff_major_stress.size() < 2 || p.ff_major_stress.size() != p.ff_strength.size())
      problems.push_back({"ff_strength", "a tabulated flow function needs ff_major_stress and "
                                         "ff_strength lists of the same length, at least 2 points"});
    else if (!std::is_sorted(p.ff_major_stress.begin(), p.ff_major_stress.end()) ||
             std::adjacent_find(p.ff_major_stress.begin(), p.ff_major_stress.end()) !=
                 p.ff_major_stress.end())
      problems.push_back({"ff_major_stress", "must increase strictly"});
  }
  if (p.density.size() != p.density_major_stress.size() ||
      (!p.density.empty() && p.density.size() < 2))
    problems.push_back({"density", "a compressibility table needs density_major_stress and density lists of "
                                   "the same length, at least 2 points"});
  else if (!std::is_sorted(p.density_major_stress.begin(), p.density_major_stress.end()))
    problems.push_back({"density_major_stress", "must increase"});
  return problems;
}

std::span<const FieldSpec<SurfaceFlowProperties>> surface_flow_fields() {
  using S = SurfaceFlowProperties;
  constexpr auto opt = Presence::optional;
  static const FieldSpec<S> fields[] = {
      number_field<S>("theta1", &S::theta1, dim::angle, "deg",
                      Range::half_open(0.0, 90.0 * kDegree),
                      "angle below which every layer stays at rest (mu_s = tan theta1)"),
      number_field<S>("theta2", &S::theta2, dim::angle, "deg", Range::open(0.0, 90.0 * kDegree),
                      "angle above which no layer stops (mu_2 = tan theta2)"),
      number_field<S>("stop_length", &S::stop_length, dim::length, "mm", Range{0.0, 1.0, false, true},
                      "length L of Pouliquen's h_stop law"),
      number_field<S>("flow_rule_beta", &S::flow_rule_beta, dim::dimensionless, "-",
                      Range::positive(), "beta of the flow rule Fr = beta h/h_stop - Gamma", opt),
      number_field<S>("flow_rule_gamma", &S::flow_rule_gamma, dim::dimensionless, "-",
                      Range::non_negative(), "Gamma of the flow rule", opt),
      number_field<S>("solid_fraction", &S::solid_fraction, dim::dimensionless, "-",
                      Range::open(0.0, 1.0), "solid volume fraction of a flowing layer", opt),
      number_field<S>("cohesion", &S::cohesion, dim::pressure, "Pa", kStrengthRange,
                      "low-stress cohesion for the infinite-slope check", opt),
      number_field<S>("theta_uncertainty", &S::theta_uncertainty, dim::angle, "deg",
                      Range::closed(0.0, 10.0 * kDegree), "uncertainty of theta1 and theta2", opt),
      number_field<S>("stop_length_uncertainty", &S::stop_length_uncertainty, dim::dimensionless,
                      "%", Range::half_open(0.0, 1.0), "relative uncertainty of L", opt),
  };
  return fields;
}

std::vector<FieldProblem> check(const SurfaceFlowProperties& p) {
  if (p.theta1 < p.theta2) return {};
  return {{"theta2", "must exceed theta1 (" + format_quantity(p.theta1, "deg") + ")"}};
}

std::span<const FieldSpec<DrumFlowProperties>> drum_flow_fields() {
  using D = DrumFlowProperties;
  constexpr auto opt = Presence::optional;
  static const FieldSpec<D> fields[] = {
      number_field<D>("layer_fraction", &D::layer_fraction, dim::dimensionless, "-",
                      Range::open(0.0, 1.0), "flowing-layer thickness over the half-chord", opt),
      number_field<D>("layer_fraction_low", &D::layer_fraction_low, dim::dimensionless, "-",
                      Range::open(0.0, 1.0), "lower end of its plausible range", opt),
      number_field<D>("layer_fraction_high", &D::layer_fraction_high, dim::dimensionless, "-",
                      Range::open(0.0, 1.0), "upper end of its plausible range", opt),
      number_field<D>("end_wall_friction", &D::end_wall_friction, dim::dimensionless, "-",
                      Range::non_negative(), "friction coefficient on the drum's end walls", opt),
      number_field<D>("froude_slumping_to_rolling", &D::froude_slumping_to_rolling,
                      dim::dimensionless, "-", Range::positive(), "Froude number where rolling starts", opt),
      number_field<D>("froude_rolling_to_cascading", &D::froude_rolling_to_cascading,
                      dim::dimensionless, "-", Range::positive(), "Froude number where cascading starts", opt),
      number_field<D>("froude_cascading_to_cataracting", &D::froude_cascading_to_cataracting,
                      dim::dimensionless, "-", Range::positive(), "Froude number where cataracting starts",
                      opt),
  };
  return fields;
}

std::vector<FieldProblem> check(const DrumFlowProperties& p) {
  std::vector<FieldProblem> problems;
  if (!(p.layer_fraction_low <= p.layer_fraction && p.layer_fraction <= p.layer_fraction_high))
    problems.push_back({"layer_fraction", "must lie between layer_fraction_low and layer_fraction_high"});
  if (!(p.froude_slumping_to_rolling < p.froude_rolling_to_cascading &&
        p.froude_rolling_to_cascading < p.froude_cascading_to_cataracting &&
        p.froude_cascading_to_cataracting < 1.0))
    problems.push_back({"froude_cascading_to_cataracting",
                        "the regime thresholds must rise: slumping < rolling < cascading < "
                        "cataracting < 1 (centrifuging)"});
  return problems;
}

}  // namespace feedflow
