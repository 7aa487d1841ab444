#pragma once
// Shared vocabulary of the hopper reduced models (reduced_models.md section 1): plane (wedge,
// m = 0) or conical (m = 1) flow, the wall stress angle beta and Jenike's arch function H.
// SI units, angles in radians.
#include "models/equipment/hopper.hpp"
#include "models/core/gravity.hpp"

namespace feedflow {


enum class FlowGeometry { plane, conical };

// m = 0 for plane flow (wedge, slot outlet), 1 for conical flow (circular outlet).
constexpr int geometry_index(FlowGeometry g) { return g == FlowGeometry::plane ? 0 : 1; }
const char* to_string(FlowGeometry g);
FlowGeometry flow_geometry(const Hopper& hopper);  // wedge -> plane, conical -> conical

// beta = 1/2 [phi_w + asin(sin phi_w / sin delta)]: the angle between the wall normal and the
// major principal stress at the wall, at the Mohr-circle intersection nearer sigma1 (section 1.2).
// Throws std::invalid_argument unless 0 <= phi_w <= delta < pi/2.
double wall_stress_angle(double effective_friction_angle, double wall_friction_angle);

// Jenike's arch function H(theta): 1 + theta/180deg (plane), 2 + theta/60deg (conical),
// section 1.4. Throws std::invalid_argument for theta outside [0, pi/2).
double jenike_arch_factor(FlowGeometry g, double semi_angle);

}  // namespace feedflow
