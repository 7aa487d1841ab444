#pragma once
// Normal part `hooke`: linear spring-dashpot. k_n is either given or, as LIGGGHTS `hooke`, set
// per contact from E* and a characteristic impact speed V so that a Hertz impact at V and the
// linear spring reach the same peak overlap: k_n = (16/15) sqrt(R*) E* (15 m* V^2 /
// (16 sqrt(R*) E*))^(1/5). gamma_n = sqrt(4 m* k_n / (1 + (pi/ln e)^2)), the dashpot that
// rebounds a free linear spring with e (models.md 4.3). Hands on k_t = k_n, gamma_t = gamma_n.
#include <cmath>
#include <cstddef>
#include <string_view>

#include "models/contact/contact_kinematics.hpp"
#include "models/contact/normal_response.hpp"
#include "models/contact/restitution_damping.hpp"
#include "models/material/dem_parameters.hpp"

namespace feedflow {

class HookeNormal {
 public:
  static constexpr std::string_view kKeyword = "hooke";
  static constexpr std::string_view kSummary =
      "linear spring-dashpot, dashpot from the restitution";
  static constexpr std::size_t kHistorySize = 0;
  static constexpr bool kHasCohesionBranch = false;
  static constexpr bool kRollingOnTotalForce = false;

  struct Parameters {
    double stiffness = 0.0;                 // k_n [N/m]; 0: from E* and the speed below
    double effective_youngs_modulus = 0.0;  // E* [Pa]
    double characteristic_velocity = 1.0;   // V [m/s]
    double damping_factor = 0.0;            // 1/(1 + (pi/ln e)^2)
  };

  HookeNormal() = default;
  explicit HookeNormal(const Parameters& p) : p_(p) {}
  static HookeNormal from_material(const DemContactParameters& p,
                                   double characteristic_velocity = 1.0) {
    return HookeNormal({0.0, effective_youngs_modulus(p.youngs_modulus, p.poisson_ratio),
                        characteristic_velocity, linear_damping_factor(p.restitution)});
  }
  const Parameters& parameters() const { return p_; }

  double stiffness(const ContactInput& in) const {
    if (p_.stiffness > 0.0) return p_.stiffness;
    const double root_r = std::sqrt(in.effective_radius);
    const double v = p_.characteristic_velocity;
    return 16.0 / 15.0 * root_r * p_.effective_youngs_modulus *
           std::pow(15.0 * in.effective_mass * v * v /
                        (16.0 * root_r * p_.effective_youngs_modulus), 0.2);
  }

  NormalResponse respond(const ContactInput& in, double* /*history*/) const {
    const double k = stiffness(in);
    const double gamma = std::sqrt(4.0 * in.effective_mass * k * p_.damping_factor);
    const double elastic = k * in.overlap;
    return {elastic - gamma * in.normal_velocity, elastic, k, gamma};
  }

  double spring_stiffness(const ContactInput& in, const double* /*history*/) const {
    return stiffness(in);
  }

 private:
  Parameters p_;
};

}  // namespace feedflow
