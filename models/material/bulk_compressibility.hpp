#pragma once
// Compressibility of a bulk solid from its hypoplastic parameters: the Bauer compression law
// e_x(p) = e_x0 exp(-(3p/h_s)^n) for the limiting void ratios (x = i, c, d), and the bulk
// density rho_b = rho_s / (1 + e) they imply (reduced_models.md section 0, models.md 1.2).
#include <optional>
#include <string>

#include "models/material/hypoplastic_parameters.hpp"
#include "models/material/material.hpp"

namespace feedflow {

struct LimitVoidRatios {
  double e_d;  // densest
  double e_c;  // critical state
  double e_i;  // loosest (isotropic compression of the loosest state)
};

// Limiting void ratios at mean pressure p >= 0 [Pa].
LimitVoidRatios limit_void_ratios(const HypoplasticParameters& hp, double mean_pressure);

// Bulk density against mean pressure. The solid (envelope) density rho_s = rho_b (1 + e) is
// fixed by one reference state.
class BulkCompressibility {
 public:
  BulkCompressibility(const HypoplasticParameters& hp, double reference_density,
                      double reference_void_ratio);

  // Anchors a material: its loose density at e_i0 (poured, zero pressure) when it has one,
  // otherwise its design density at e_d0; a design density that a case or --set gave (and not
  // the loose one) anchors instead, so the user's value changes the answer. Empty when the
  // material has no hypoplastic section. Throws InputError when a case gives both densities and
  // they imply solid densities more than 5 % apart.
  static std::optional<BulkCompressibility> of(const Material& m);

  double solid_density() const { return solid_density_; }
  // Which density anchors, in words: "loose density 182 kg/m^3 at e_i0 = 1.38".
  const std::string& anchor() const { return anchor_; }
  // Bulk density at mean pressure p on the critical-state line (steady flow) [kg/m^3].
  double critical_density(double mean_pressure) const;
  // The loosest and densest bulk densities possible at p [kg/m^3].
  double loosest_density(double mean_pressure) const;
  double densest_density(double mean_pressure) const;

 private:
  HypoplasticParameters hp_;
  double solid_density_;
  std::string anchor_;
};

}  // namespace feedflow
