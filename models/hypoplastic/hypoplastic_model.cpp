#include "models/hypoplastic/hypoplastic_model.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

namespace feedflow {
namespace {

void require(bool ok, const char* what) {
  if (!ok) throw std::invalid_argument(std::string("hypoplastic parameters: ") + what);
}

}  // namespace

HypoplasticConstants hypoplastic_constants(const HypoplasticParameters& p) {
  require(p.phi_c > 0.0 && p.phi_c < std::numbers::pi / 2, "phi_c must lie in (0, 90 deg)");
  require(p.h_s > 0.0, "h_s must be > 0");
  require(p.n > 0.0 && p.n < 1.0, "n must lie in (0, 1)");
  require(p.e_d0 > 0.0 && p.e_d0 < p.e_c0 && p.e_c0 < p.e_i0, "need 0 < e_d0 < e_c0 < e_i0");
  require(p.alpha >= 0.0, "alpha must be >= 0");
  require(p.beta >= 0.0, "beta must be >= 0");
  HypoplasticConstants c;
  c.sin_phi_c = std::sin(p.phi_c);
  c.c1 = std::sqrt(3.0 / 8.0) * (3.0 - c.sin_phi_c) / c.sin_phi_c;
  c.c2 = 3.0 / 8.0 * (3.0 + c.sin_phi_c) / c.sin_phi_c;
  c.f_di = std::pow((p.e_i0 - p.e_d0) / (p.e_c0 - p.e_d0), p.alpha);
  c.h_i = 1.0 / (c.c1 * c.c1) + 1.0 / 3.0 - c.f_di / (c.c1 * std::sqrt(3.0));
  c.vw_a = std::sqrt(3.0) * (3.0 - c.sin_phi_c) / (2.0 * std::sqrt(2.0) * c.sin_phi_c);
  c.vw_denominator = 3.0 + c.vw_a * c.vw_a - std::sqrt(3.0) * c.vw_a * c.f_di;
  require(c.h_i > 0.0 && c.vw_denominator > 0.0,
          "e_i0, e_c0, e_d0 and alpha give a non-positive stiffness normalisation h_i");
  return c;
}

HypoplasticModel make_hypoplastic_model(const HypoplasticParameters& p, HypoplasticVariant variant,
                                        const HypoplasticSafeguards& safeguards) {
  if (!(safeguards.tension_reset_stress > 0.0) || !(safeguards.zero_stress_tolerance > 0.0) ||
      !(safeguards.minimum_pressure >= 0.0))
    throw std::invalid_argument(
        "hypoplastic safeguards: tension_reset_stress and zero_stress_tolerance must be > 0, "
        "minimum_pressure >= 0");
  return {p, hypoplastic_constants(p), variant, safeguards};
}

HypoplasticParameters loblolly_pine_table1() {
  return {47.3 * std::numbers::pi / 180.0, 187.6e3, 0.30, 0.50, 1.06, 1.38, 0.3, 1.0};
}

}  // namespace feedflow
