#pragma once
// The eight Gudehus-Bauer hypoplastic parameters (seed Table 1; models.md section 1.4).
#include <span>
#include <vector>

#include "models/core/field_spec.hpp"

namespace feedflow {

struct HypoplasticParameters {
  double phi_c = 0.0;  // critical-state friction angle [rad]
  double h_s = 0.0;    // granulate hardness [Pa]
  double n = 0.0;      // exponent of the compression law [-]
  double e_d0 = 0.0;   // minimum void ratio at zero pressure [-]
  double e_c0 = 0.0;   // critical void ratio at zero pressure [-]
  double e_i0 = 0.0;   // maximum void ratio at zero pressure [-]
  double alpha = 0.0;  // exponent of the density factor f_d (peak friction) [-]
  double beta = 0.0;   // exponent of the stiffness factor (e_i/e)^beta [-]
};

std::span<const FieldSpec<HypoplasticParameters>> hypoplastic_fields();
std::vector<FieldProblem> check(const HypoplasticParameters& p);

}  // namespace feedflow
