#pragma once
// Normal part `hysteretic_nonlinear1`: the older Chen/INL variant with linear unloading and
// the cohesion branch F = -k_c delta below delta_min (models.md 3.4; LIGGGHTS-INL
// `hysteretic/nonlinear1`). Loading and branch choice are those of nonlinear2; damping uses
// delta^(1/4): loading g(k1)(delta^1/4 + delta0^1/4), unloading g(k1_old) delta^1/4.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <string_view>

#include "models/contact/contact_kinematics.hpp"
#include "models/contact/hysteretic_parameters.hpp"
#include "models/contact/normal_response.hpp"

namespace feedflow {

class HystereticNonlinear1 {
 public:
  static constexpr std::string_view kKeyword = "hysteretic_nonlinear1";
  static constexpr std::string_view kSummary =
      "Chen hysteretic law, linear unloading, K_nc cohesion branch";
  static constexpr std::size_t kHistorySize = hysteretic_slot::count;
  static constexpr bool kHasCohesionBranch = true;
  static constexpr bool kFirstSlotMarksUse = true;  // delta_max > 0 once the contact has touched
  static constexpr bool kRollingOnTotalForce = true;

  HystereticNonlinear1() = default;
  explicit HystereticNonlinear1(const HystereticParameters& p) : p_(p) {}
  static HystereticNonlinear1 from_material(const DemContactParameters& p) {
    return HystereticNonlinear1(HystereticParameters::from_material(p));
  }
  const HystereticParameters& parameters() const { return p_; }
  // Model 1's -k_c delta branch is part of the peer's law (clipped by limitForce unless the
  // cohesion part lets contacts pull): the cohesive law is the same.
  HystereticNonlinear1 cohesive() const { return *this; }

  NormalResponse respond(const ContactInput& in, double* h) const {
    namespace s = hysteretic_slot;
    const double d = in.overlap;
    const double d_old = h[s::previous_overlap];
    const double d0 = h[s::plastic_overlap];
    const double dmax = std::max(h[s::max_overlap], d);
    h[s::max_overlap] = dmax;
    const bool loading = d >= d_old && (d_old == 0.0 || in.normal_velocity <= 0.0);
    const double kc = p_.cohesion_stiffness;
    double f = 0.0;
    double gamma = 0.0;
    double k1 = 0.0;
    if (loading) {
      k1 = d0 == 0.0 ? p_.a2 : h[s::loading_stiffness];
      h[s::loading_offset_old] = h[s::loading_offset];
      if (d > d0) {
        f = p_.alpha * k1 * (d - d0) * (d - d0) + h[s::loading_offset];
      } else {
        f = d >= h[s::cohesion_overlap] ? h[s::unloading_shape] * (d - d0) : -kc * d;
      }
      h[s::plastic_overlap_old] = d0;
      h[s::loading_stiffness_old] = k1;
      h[s::loading_stiffness] = k1;
      h[s::previous_overlap] = d;
      gamma = damping_scale(in.effective_mass, k1) * (quarter_power(d) + quarter_power(d0));
    } else {
      const double k1_old = h[s::loading_stiffness_old];
      const double d0_old = h[s::plastic_overlap_old];
      const double k2 = p_.a3 * k1_old;
      const double d0_new = (1.0 - 1.0 / p_.a3) * dmax;
      const double beta = p_.alpha * k1_old * (dmax - d0_old) * (dmax - d0_old) /
                          (k2 * (dmax - d0_new));
      const double dmin = beta * (k2 - k1_old) / (beta * k2 + kc) * dmax;
      k1 = p_.a1 * dmax + p_.a2;
      const double x = d - d0_new;
      if (d >= d0_new) {
        f = beta * k2 * x + x * h[s::loading_offset_old] / (dmax - d0_new);
        h[s::loading_offset] = f - p_.alpha * k1 * x * x;
        h[s::unloading_shape] = beta * k2;
      } else if (d >= dmin) {
        f = beta * k2 * x;
        h[s::loading_offset] = 0.0;
        h[s::unloading_shape] = beta * k2;
      } else {  // jumped below delta_min: beta_n keeps its stored value (models.md 3.4)
        f = -kc * d;
        h[s::loading_offset] = 0.0;
      }
      h[s::plastic_overlap] = d0_new;
      h[s::loading_stiffness] = k1;
      h[s::previous_overlap] = d;
      h[s::cohesion_overlap] = dmin;
      gamma = damping_scale(in.effective_mass, k1_old) * quarter_power(d);
    }
    return {f - gamma * in.normal_velocity, f, k1, gamma};
  }

  // Largest of the loading slope at the current overlap and the linear unloading slope that a
  // reversal at delta_max would follow.
  double spring_stiffness(const ContactInput& in, const double* h) const {
    namespace s = hysteretic_slot;
    const double dmax = h[s::max_overlap];
    if (dmax <= 0.0) return 0.0;
    const double k1 = h[s::loading_stiffness];
    const double loading = 2.0 * p_.alpha * k1 * std::max(in.overlap - h[s::plastic_overlap], 0.0);
    const double k1_old = h[s::loading_stiffness_old];
    const double d0_old = h[s::plastic_overlap_old];
    const double d0_new = (1.0 - 1.0 / p_.a3) * dmax;
    const double peak = p_.alpha * k1_old * (dmax - d0_old) * (dmax - d0_old);
    const double unloading = (peak + h[s::loading_offset_old]) / (dmax - d0_new);
    return std::max(loading, unloading);
  }

 private:
  static double quarter_power(double x) { return std::sqrt(std::sqrt(x)); }
  double damping_scale(double mass, double stiffness) const {
    return std::sqrt(4.0 * mass * p_.alpha * stiffness * p_.damping_factor);
  }
  HystereticParameters p_;
};

}  // namespace feedflow
