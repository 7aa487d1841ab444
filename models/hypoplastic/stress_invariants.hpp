#pragma once
// Soil-mechanics measures of a Cauchy stress (tension positive): mean pressure p, deviatoric
// stress q, and the mobilised friction angle from the principal stresses.
#include <Eigen/Core>

namespace feedflow {

// p = -tr T / 3 [Pa]
double mean_pressure(const Eigen::Matrix3d& stress);
// q = sqrt(3/2 s:s), s the deviator [Pa]
double deviatoric_stress(const Eigen::Matrix3d& stress);
// phi_m = asin((s1 - s3)/(s1 + s3)) for the principal compressive stresses s1 >= s3 [rad];
// pi/2 when s3 <= 0 (no frictional resistance left).
double mobilised_friction_angle(const Eigen::Matrix3d& stress);

}  // namespace feedflow
