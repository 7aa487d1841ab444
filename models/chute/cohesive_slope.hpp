#pragma once
// Stopping thickness of a cohesive layer: the Mohr-Coulomb infinite slope and the heuristic
// hybrid with Pouliquen's law (reduced_models.md section 3 item 4).
#include "models/chute/pouliquen_law.hpp"

namespace feedflow {

struct CohesiveSlope {
  double cohesion = 0.0;        // low-stress cohesion c [Pa]
  double friction_angle = 0.0;  // phi [rad]
  double bulk_density = 0.0;    // rho_b [kg/m^3]
};

// Failure at the base of an infinite slope: rho g z sin cos = c + rho g z cos^2 tan(phi) with z
// the VERTICAL depth, so z_c = c/(rho g cos^2 (tan theta - tan phi)) (the reference's formula).
// `thickness` is the depth normal to the plane, z_c cos(theta), comparable with Pouliquen's h.
// theta <= phi never fails (infinite); c = 0 above phi holds nothing (no deposit).
struct CohesiveStop {
  StoppingThickness normal;  // thickness normal to the plane
  double vertical_depth;     // z_c [m] (infinite or 0 like `normal`)
};
CohesiveStop cohesive_stopping_depth(const CohesiveSlope& slope, double angle);

// Hybrid [heuristic]: h_stop = [L (tan theta2 - tan theta) + c/(rho_b g cos theta)]/(tan theta -
// tan theta1), all thicknesses normal to the plane. NOTE: reduced_models.md writes the cohesive
// term as c/(rho_b g cos^2 theta), which mixes its vertical depth z_c into Pouliquen's normal
// thickness; here the normal-thickness form c/(rho_b g cos theta) is used so that L -> 0 gives
// exactly the infinite-slope thickness z_c cos(theta) with phi = theta1.
// Cohesion keeps a deposit above theta2 as long as the numerator stays positive.
StoppingThickness hybrid_stopping_thickness(const PouliquenLaw& law, double cohesion,
                                            double bulk_density, double angle);

}  // namespace feedflow
