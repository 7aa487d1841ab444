#pragma once
// Critical outlet width against cohesive arching (reduced_models.md sections 1.4 and 1.5):
// Jenike's B_c = H(theta) sigma_c,crit / (rho_b g), where the flow function meets the flow
// factor line sigma_c = sigma1/ff; the static-arch (wall-friction-limited) second estimate
// H_a(theta, phi_w); the mechanical (interlocking) arching width (3-8) d_max; the slot-length
// rule L >= 3B.
#include <string>

#include "models/hopper/flow_function.hpp"
#include "models/hopper/hopper_geometry.hpp"

namespace feedflow {

enum class ArchingOutcome {
  critical_width,     // arches below a finite width B_c
  no_cohesive_arch,   // the flow function lies below the ff line everywhere: B_c = 0
  no_gravity_outlet,  // above it everywhere (or again at high stress): flow aids needed
};
const char* to_string(ArchingOutcome o);
// The label of the `arching` estimate: "cohesive arch below B_c", "no cohesive arch",
// "no gravity outlet".
const char* arching_label(ArchingOutcome o);

// Where F(sigma1*) = sigma1*/ff. Closed form for linear and power-law flow functions, GSL
// Brent on the bracketing table segment for a tabulated one.
struct CriticalPoint {
  ArchingOutcome outcome;
  double major_stress;  // sigma1* [Pa]; 0 unless critical_width
  double strength;      // sigma_c,crit = sigma1*/ff [Pa]; 0 unless critical_width
  bool extrapolated;    // sigma1* lies outside a tabulated flow function's points
};
CriticalPoint critical_point(const FlowFunction& ff_curve, double flow_factor);

struct CriticalOutlet {
  ArchingOutcome outcome;
  double width;              // [m]; 0 (no cohesive arch) or +infinity (no gravity outlet)
  double arch_factor;        // H(theta) or H_a(theta, phi_w)
  double major_stress;       // sigma1* [Pa]
  double critical_strength;  // sigma_c,crit [Pa]
  double bulk_density;       // rho_b(sigma1*) [kg/m^3]
  bool extrapolated;         // the flow function was read beyond its table
  std::string model;

  std::string statement() const;  // the outcome in words (made when asked: sweeps never ask)
};

// B = arch_factor * strength / (rho_b g) [m].
double arching_width(double arch_factor, double strength, double bulk_density,
                     double gravity = kGravity);

// Jenike: B_c = H(theta) sigma_c,crit / (rho_b(sigma1*) g).
CriticalOutlet jenike_critical_outlet(FlowGeometry g, double semi_angle, double flow_factor,
                                      const FlowFunction& ff_curve, const BulkDensity& density,
                                      double gravity = kGravity);

// Static-arch factor of a plane hopper, arch meeting the wall at phi_w (section 1.5):
// H_a = 2 cos phi_w sin^3(theta+phi_w) / [(theta+phi_w) sin theta + sin(theta+phi_w) sin phi_w].
double static_arch_factor(double semi_angle, double wall_friction_angle);

// The same critical point with H_a in place of H (plane hoppers: a second estimate that
// falls on steep smooth walls, where the arch loses its wall support).
CriticalOutlet static_arch_critical_outlet(double semi_angle, double wall_friction_angle,
                                           double flow_factor, const FlowFunction& ff_curve,
                                           const BulkDensity& density, double gravity = kGravity);

// Mechanical (interlocking) arching, outside continuum theory: B ~ (3...8) d_max.
struct MechanicalArching {
  double low;   // low_multiple * d_max [m]
  double high;  // high_multiple * d_max [m]
  std::string model;
};
MechanicalArching mechanical_arching_width(double largest_particle_size, double low_multiple = 3.0,
                                           double high_multiple = 8.0);

// Plane flow needs a slot at least 3 outlet widths long.
double minimum_slot_length(double outlet_width);
bool slot_length_sufficient(double slot_length, double outlet_width);

}  // namespace feedflow
