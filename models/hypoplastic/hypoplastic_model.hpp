#pragma once
// A hypoplastic material as the stress integrator sees it: the eight parameters, the constants
// derived from them once (c1, c2, h_i, ...), the variant of the rate law and the seed authors'
// safeguards (models.md sections 1.2-1.6). Plain data, cheap to copy, no allocation.
#include "models/material/hypoplastic_parameters.hpp"

namespace feedflow {

// Which rate law: the Gudehus-Bauer form the seed authors used (models.md 1.2), or the
// von Wolffersdorff (1996) form for comparison (1.3). Chosen per model, switched without virtual
// calls on the hot path.
enum class HypoplasticVariant { gudehus_bauer, von_wolffersdorff };

// The safeguards of the INL VUMAT (models.md 1.5), each switchable. f_d = 0 for e <= e_d is not
// switchable: without it f_d is a negative number raised to a fractional power (undefined).
struct HypoplasticSafeguards {
  // Per normal component: T_kk >= 0 is reset to -tension_reset_stress (INL: 10.00001 Pa), on the
  // input stress of a step and after every substep. Shear components are left alone.
  bool tension_reset = true;
  double tension_reset_stress = 10.00001;  // [Pa], the p_floor of models.md 1.6
  // Void ratio clamped to [1.001 e_d, 0.999 e_i], both evaluated at the stress before the
  // (sub)step.
  bool void_ratio_clamp = true;
  // Near-zero stress (|tr T| below this, or tension): the rate is the isotropic compression-law
  // rate at 3p = tolerance when compressed (tr D < 0, e <= e_i0) and zero otherwise (INL branch).
  double zero_stress_tolerance = 1e-3;  // [Pa]
  // Optional smooth cutoff instead of relying on the reset alone: if p < minimum_pressure the
  // stress is shifted isotropically to p = minimum_pressure after every substep. 0 = off.
  double minimum_pressure = 0.0;  // [Pa]
};

// Constants of the rate law computed once from the parameters (models.md 1.2 items 5 and 8,
// 1.3, 1.4).
struct HypoplasticConstants {
  double sin_phi_c = 0.0;
  double c1 = 0.0;         // sqrt(3/8)(3 - sin phi_c)/sin phi_c (= von Wolffersdorff a)
  double c2 = 0.0;         // (3/8)(3 + sin phi_c)/sin phi_c
  double h_i = 0.0;        // 1/c1^2 + 1/3 - f_di/(c1 sqrt 3)
  double f_di = 0.0;       // ((e_i0 - e_d0)/(e_c0 - e_d0))^alpha
  double vw_a = 0.0;       // von Wolffersdorff a
  double vw_denominator = 0.0;  // 3 + a^2 - sqrt(3) a f_di
};

struct HypoplasticModel {
  HypoplasticParameters parameters;
  HypoplasticConstants constants;
  HypoplasticVariant variant = HypoplasticVariant::gudehus_bauer;
  HypoplasticSafeguards safeguards;
};

// Derived constants; throws std::invalid_argument naming the parameter when the parameters are
// not admissible (phi_c in (0, 90 deg), h_s > 0, 0 < n < 1, 0 < e_d0 < e_c0 < e_i0, alpha >= 0,
// beta >= 0).
HypoplasticConstants hypoplastic_constants(const HypoplasticParameters& p);

HypoplasticModel make_hypoplastic_model(const HypoplasticParameters& p,
                                        HypoplasticVariant variant = HypoplasticVariant::gudehus_bauer,
                                        const HypoplasticSafeguards& safeguards = {});

// The seed's Table 1 (milled loblolly pine), for tests, benchmarks and examples.
HypoplasticParameters loblolly_pine_table1();

}  // namespace feedflow
