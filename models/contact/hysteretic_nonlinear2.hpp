#pragma once
// Normal part `hysteretic_nonlinear2`: Chen et al. (2022) hysteretic law with exponential
// unloading, seed Eq. 7, exactly as models.md 3.3 (LIGGGHTS-INL `hysteretic/nonlinear2`),
// including its quirks: branch choice from the overlap and the normal velocity, the offsets
// that make reloading continuous, the damping forms (loading g(k1)(sqrt(delta)+sqrt(delta0)),
// unloading 0.001 g(k1_old) delta^-1/4) and k_t = k1, gamma_t = gamma_n handed on.
// Cohesion (models.md 3.5, [I]): with the k_nc cohesion part (`cohesive()`), below delta0 the
// force is max(exponential tail, -k_c delta), the same construction as model 1. Without it there
// is no floor, as in the peer: the tail, the damping, then the clip at zero.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <string_view>

#include "models/contact/contact_kinematics.hpp"
#include "models/contact/hysteretic_parameters.hpp"
#include "models/contact/normal_response.hpp"
#include "models/numerics/lane_math.hpp"

namespace feedflow {

class HystereticNonlinear2 {
 public:
  static constexpr std::string_view kKeyword = "hysteretic_nonlinear2";
  static constexpr std::string_view kSummary =
      "Chen 2022 hysteretic law, exponential unloading (seed Eq. 7)";
  static constexpr std::size_t kHistorySize = hysteretic_slot::count;
  static constexpr bool kHasCohesionBranch = true;
  static constexpr bool kFirstSlotMarksUse = true;    // delta_max > 0 once the contact has touched
  static constexpr bool kRollingOnTotalForce = true;  // INL `cdtnonlinear2`: F_ref = F_n

  HystereticNonlinear2() = default;
  explicit HystereticNonlinear2(const HystereticParameters& p) : p_(p) {}
  static HystereticNonlinear2 from_material(const DemContactParameters& p) {
    return HystereticNonlinear2(HystereticParameters::from_material(p));
  }
  const HystereticParameters& parameters() const { return p_; }
  // The law as it acts when the cohesion part lets contacts pull: with the -k_c delta floor.
  HystereticNonlinear2 cohesive() const {
    HystereticNonlinear2 law = *this;
    law.p_.cohesion_floor = true;
    return law;
  }

  // Both branches are computed and the history written through selects (no branch, no call:
  // lane_math's exp and log), so the pair loop's batch runs this as one vector loop; a branch's
  // values in a lane that takes the other (e.g. a division by zero on a first contact's
  // unloading side) are computed and dropped.
  NormalResponse respond(const ContactInput& in, double* h) const {
    namespace s = hysteretic_slot;
    const double d = in.overlap;
    const double d_old = h[s::previous_overlap];
    const double d0 = h[s::plastic_overlap];
    const double dmax = std::max(h[s::max_overlap], d);
    const double f0 = h[s::loading_offset];
    const double k1_stored = h[s::loading_stiffness];
    const double k1_old = h[s::loading_stiffness_old];
    const double d0_old = h[s::plastic_overlap_old];
    const double f0_old = h[s::loading_offset_old];
    // Bitwise, not short-circuit: g++ does not if-convert && and || in a vector loop.
    const bool loading = (d >= d_old) & ((d_old == 0.0) | (in.normal_velocity <= 0.0));

    // Loading (models.md 3.3 step 3): on the loading curve above delta0, below it back up the
    // last unloading curve.
    const double k1_loading = d0 == 0.0 ? p_.a2 : k1_stored;
    const double above = p_.alpha * k1_loading * (d - d0) * (d - d0) + f0;
    const double below = floored(
        p_.c * p_.a3 * k1_loading * (lane_math::exp(h[s::unloading_shape] * (d - d0)) - 1.0), d);
    const double f_loading = d > d0 ? above : below;
    const double gamma_loading =
        damping_scale(in.effective_mass, k1_loading) * (std::sqrt(d) + std::sqrt(d0));

    // Unloading (step 4): the exponential curve from the largest overlap, recomputed each step.
    const double k2 = p_.a3 * (p_.a1 * dmax + p_.a2);
    const double d0_new = (1.0 - k1_old / k2) * dmax;
    const double beta =
        lane_math::log(p_.alpha * k1_old * (dmax - d0_old) * (dmax - d0_old) / (p_.c * k2) + 1.0) /
        (dmax - d0_new);
    const double k1_next = p_.a1 * dmax + p_.a2;
    const double x = d - d0_new;
    const double tail = p_.c * k2 * (lane_math::exp(beta * x) - 1.0);
    const bool on_ramp = d >= d0_new;
    const double ramp = tail + x * f0_old / (dmax - d0_new);
    const double f_unloading = on_ramp ? ramp : floored(tail, d);
    const double gamma_unloading =
        0.001 * damping_scale(in.effective_mass, k1_old) / std::sqrt(std::sqrt(d));

    h[s::max_overlap] = dmax;
    h[s::previous_overlap] = d;
    h[s::loading_offset_old] = loading ? f0 : f0_old;
    h[s::plastic_overlap_old] = loading ? d0 : d0_old;
    h[s::loading_stiffness_old] = loading ? k1_loading : k1_old;
    h[s::loading_stiffness] = loading ? k1_loading : k1_next;
    h[s::plastic_overlap] = loading ? d0 : d0_new;
    h[s::unloading_shape] = loading ? h[s::unloading_shape] : beta;
    h[s::loading_offset] = loading ? f0 : (on_ramp ? ramp - p_.alpha * k1_next * x * x : 0.0);
    const double f = loading ? f_loading : f_unloading;
    const double gamma = loading ? gamma_loading : gamma_unloading;
    return {f - gamma * in.normal_velocity, f, loading ? k1_loading : k1_next, gamma};
  }

  // Largest of the loading slope at the current overlap and the slope of the unloading curve
  // that a reversal at delta_max would follow (models.md 5.1), from the history after respond.
  double spring_stiffness(const ContactInput& in, const double* h) const {
    namespace s = hysteretic_slot;
    const double dmax = h[s::max_overlap];
    if (dmax <= 0.0) return 0.0;
    const double k1 = h[s::loading_stiffness];
    const double loading = 2.0 * p_.alpha * k1 * std::max(in.overlap - h[s::plastic_overlap], 0.0);
    const double k1_old = h[s::loading_stiffness_old];
    const double d0_old = h[s::plastic_overlap_old];
    const double k2 = p_.a3 * (p_.a1 * dmax + p_.a2);
    const double d0_new = (1.0 - k1_old / k2) * dmax;
    const double peak = p_.alpha * k1_old * (dmax - d0_old) * (dmax - d0_old);
    const double beta = lane_math::log(peak / (p_.c * k2) + 1.0) / (dmax - d0_new);
    const double unloading = beta * (peak + p_.c * k2) +
                             h[s::loading_offset_old] / (dmax - d0_new);
    return std::max(loading, unloading);
  }

 private:
  // g = sqrt(4 m* alpha K / (1 + (pi/ln e)^2)) (models.md 3.3 step 5)
  double damping_scale(double mass, double stiffness) const {
    return std::sqrt(4.0 * mass * p_.alpha * stiffness * p_.damping_factor);
  }
  // Below delta0 with the k_nc cohesion part: no more attractive than -k_c delta.
  double floored(double f, double d) const {
    const double floor = -p_.cohesion_stiffness * d;
    return (p_.cohesion_floor & (f < floor)) ? floor : f;
  }
  HystereticParameters p_;
};

}  // namespace feedflow
