#pragma once
// Janssen stresses in the vertical bin above a hopper (reduced_models.md section 5):
// sigma_v(z) = (rho_b g A/(lambda mu_w U)) [1 - exp(-lambda mu_w U z / A)]
//            + sigma_v0 exp(-lambda mu_w U z / A),
// wall normal sigma_n = lambda sigma_v, wall shear tau_w = mu_w sigma_n. An intermediate result
// for reports; also the transition stress the hopper slice starts from.
#include <optional>
#include <vector>

#include "models/hopper/hopper_geometry.hpp"

namespace feedflow {

enum class StressRatioRule {
  jaky,            // 1 - sin phi
  en1991_4,        // 1.1 (1 - sin phi_i)
  schulze,         // 1.2 (1 - sin phi_e), flow design [REC]
  rankine_active,  // (1 - sin phi)/(1 + sin phi)
};
const char* to_string(StressRatioRule rule);
// Janssen's lambda = sigma_h / sigma_v from the rule and its friction angle [rad].
double janssen_stress_ratio(StressRatioRule rule, double friction_angle);

// A/U of the bin cross-section [m]: plane bin of width D_b between the long walls and length
// L_b (A/U = D_b L_b / (2 (D_b + L_b)), D_b/2 for an endless slot); round bin D/4.
double plane_bin_hydraulic_radius(double width, std::optional<double> length = std::nullopt);
double round_bin_hydraulic_radius(double diameter);

struct JanssenBin {
  double hydraulic_radius;      // A/U [m]
  double bulk_density;          // rho_b [kg/m^3]
  double stress_ratio;          // lambda
  double wall_friction;         // mu_w = tan phi_w
  double surcharge = 0.0;       // sigma_v0 on the top surface [Pa]
  double gravity = kGravity;    // [m/s^2]
};

struct BinStressPoint {
  double depth;        // below the top surface [m]
  double vertical;     // sigma_v [Pa]
  double wall_normal;  // sigma_n [Pa]
  double wall_shear;   // tau_w [Pa]
};

// The deep-bin limit rho_b g A/(lambda mu_w U) [Pa].
double janssen_asymptotic_stress(const JanssenBin& bin);
// The depth at which sigma_v reaches `fraction` of the asymptote, without surcharge [m].
double janssen_depth_to_fraction(const JanssenBin& bin, double fraction);
BinStressPoint janssen_stress(const JanssenBin& bin, double depth);
// `points` depths evenly spaced from the surface to `depth`.
std::vector<BinStressPoint> janssen_profile(const JanssenBin& bin, double depth, int points = 50);

}  // namespace feedflow
