#pragma once
// The reduced models' view of a bulk solid, each a material section:
// - FlowProperties [flow_properties]: Jenike's flow properties for hopper design: the flow
//   function sigma_c(sigma1), the effective angle of internal friction and their uncertainty;
// - SurfaceFlowProperties [surface_flow]: Pouliquen's h_stop law and flow rule (chutes, and the
//   mu(I) flowing layer of drums);
// - DrumFlowProperties [drum_flow]: the flowing-layer closure and the regime thresholds.
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "models/core/field_spec.hpp"

namespace feedflow {

struct FlowProperties {
  std::string flow_function = "linear";   // "linear", "power_law" or "tabulated"
  double ff_slope = 0.0;                  // linear: sigma_c = slope sigma1 + intercept [-]
  double ff_intercept = 0.0;              // [Pa]
  double ff_coefficient = 0.0;            // power law: sigma_c = coefficient sigma1^exponent (Pa)
  double ff_exponent = 1.0;               // [-]
  std::vector<double> ff_major_stress;    // tabulated sigma1 [Pa]
  std::vector<double> ff_strength;        // tabulated sigma_c [Pa]
  double ff_uncertainty = 0.3;            // relative +- on sigma_c [-]
  double effective_friction_angle = 0.0;  // delta [rad]
  double effective_friction_uncertainty = 0.05235987755982988;  // +- on delta [rad] (3 deg)
  double wall_friction_uncertainty = 0.03490658503988659;      // +- on phi_w [rad] (2 deg)
  std::vector<double> density_major_stress;  // measured compressibility: sigma1 [Pa] ...
  std::vector<double> density;               // ... and the bulk density there [kg/m^3]
};

struct SurfaceFlowProperties {
  double theta1 = 0.0;              // below it every layer is static [rad]
  double theta2 = 0.0;              // above it no layer stops [rad]
  double stop_length = 0.0;         // L of h_stop = L (tan theta2 - tan theta)/(tan theta - tan theta1) [m]
  double flow_rule_beta = 0.136;    // beta_P of Fr = beta h/h_stop - Gamma [-]
  double flow_rule_gamma = 0.0;     // Gamma [-]
  double solid_fraction = 0.6;      // phi of a flowing layer [-]
  double cohesion = 0.0;            // low-stress cohesion c of the infinite-slope check [Pa]
  double theta_uncertainty = 0.017453292519943295;  // +- on theta1 and theta2 [rad] (1 deg)
  double stop_length_uncertainty = 0.3;             // relative +- on L [-]
};

struct DrumFlowProperties {
  double layer_fraction = 0.2;         // c_delta = flowing-layer thickness / half-chord [-]
  double layer_fraction_low = 0.1;     // its plausible range, for the band
  double layer_fraction_high = 0.3;
  double end_wall_friction = 0.0;      // mu_ew on the drum's end walls [-]
  double froude_slumping_to_rolling = 1e-4;
  double froude_rolling_to_cascading = 0.1;
  double froude_cascading_to_cataracting = 0.5;
};

std::span<const FieldSpec<FlowProperties>> flow_property_fields();
std::vector<FieldProblem> check(const FlowProperties& p);
std::span<const FieldSpec<SurfaceFlowProperties>> surface_flow_fields();
std::vector<FieldProblem> check(const SurfaceFlowProperties& p);
std::span<const FieldSpec<DrumFlowProperties>> drum_flow_fields();
std::vector<FieldProblem> check(const DrumFlowProperties& p);

}  // namespace feedflow
