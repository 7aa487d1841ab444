#pragma once
// Normal part `hertz`: Hertz spring with a dashpot scaled from the restitution (models.md 4.3):
// k_n = (4/3) E* sqrt(R* delta), S_n = 2 E* sqrt(R* delta), gamma_n = c sqrt(S_n m*),
// F_n = k_n delta - gamma_n v_n. Hands on the Mindlin pair S_t = 8 G* sqrt(R* delta),
// gamma_t = c sqrt(S_t m*) (as LIGGGHTS `hertz` + `tangential history`). By default c makes an
// impact rebound with exactly e (restitution_damping.hpp); HertzDampingForm::liggghts gives
// the peer's c = -2 sqrt(5/6) beta_e.
#include <cmath>
#include <cstddef>
#include <string_view>

#include "models/contact/contact_kinematics.hpp"
#include "models/contact/normal_response.hpp"
#include "models/contact/restitution_damping.hpp"
#include "models/material/dem_parameters.hpp"

namespace feedflow {

class HertzNormal {
 public:
  static constexpr std::string_view kKeyword = "hertz";
  static constexpr std::string_view kSummary = "Hertz spring, dashpot from the restitution";
  static constexpr std::size_t kHistorySize = 0;
  static constexpr bool kHasCohesionBranch = false;
  static constexpr bool kRollingOnTotalForce = false;  // LIGGGHTS `cdt`: F_ref = k_n delta

  struct Parameters {
    double effective_youngs_modulus = 0.0;  // E* [Pa]
    double effective_shear_modulus = 0.0;   // G* [Pa]
    double damping_coefficient = 0.0;       // c [-]
  };

  HertzNormal() = default;
  explicit HertzNormal(const Parameters& p) : p_(p) {}
  static HertzNormal from_material(const DemContactParameters& p,
                                   HertzDampingForm form = HertzDampingForm::restitution_exact) {
    return HertzNormal({effective_youngs_modulus(p.youngs_modulus, p.poisson_ratio),
                        effective_shear_modulus(p.youngs_modulus, p.poisson_ratio),
                        hertz_damping_coefficient(p.restitution, form)});
  }
  const Parameters& parameters() const { return p_; }

  NormalResponse respond(const ContactInput& in, double* /*history*/) const {
    const double root = std::sqrt(in.effective_radius * in.overlap);
    const double sn = 2.0 * p_.effective_youngs_modulus * root;
    const double st = 8.0 * p_.effective_shear_modulus * root;
    const double elastic = (2.0 / 3.0) * sn * in.overlap;  // (4/3) E* sqrt(R* delta) delta
    const double gamma_n = p_.damping_coefficient * std::sqrt(sn * in.effective_mass);
    const double gamma_t = p_.damping_coefficient * std::sqrt(st * in.effective_mass);
    return {elastic - gamma_n * in.normal_velocity, elastic, st, gamma_t};
  }

  // dF/d delta = 2 E* sqrt(R* delta) = S_n.
  double spring_stiffness(const ContactInput& in, const double* /*history*/) const {
    return 2.0 * p_.effective_youngs_modulus * std::sqrt(in.effective_radius * in.overlap);
  }

 private:
  Parameters p_;
};

}  // namespace feedflow
