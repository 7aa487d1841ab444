#pragma once
// Rolling parts (models.md 4.4), acting on the rolling part of omega_r = omega_i - omega_j
// (its normal component, torsion, is left alone):
// - `cdt`: constant directional torque (Zhou et al. 1999) M = -mu_r R* F_ref omega_t/|omega_r|,
//   F_ref = k_n delta for hertz/hooke (LIGGGHTS `cdt`), F_n for the hysteretic laws (INL
//   `cdtnonlinear2`, clipped at zero). It chatters near rest: the torque flips with omega.
// - `cdt_clamped`: the same torque, capped at I_eff |omega_t| / dt so that one step can stop
//   the rolling but never reverse it ([I], models.md 4.4).
// - `epsd2` (Wensrich & Katterfeld 2012): spring torque M_k -= k_r omega_t dt with
//   k_r = k_t R*^2, capped at mu_r R* |F_n|, no dashpot. History: the three components of M_k.
#include <cmath>
#include <cstddef>
#include <string_view>

#include <Eigen/Core>

#include "models/contact/contact_kinematics.hpp"
#include "models/material/dem_parameters.hpp"

namespace feedflow {

// What a rolling part receives besides the contact input.
struct RollingLoad {
  double reference_force = 0.0;       // F_ref of the constant-torque laws [N]
  double normal_force = 0.0;          // F_n after clipping [N]
  double tangential_stiffness = 0.0;  // k_t [N/m]
};

class NoRolling {
 public:
  static constexpr std::string_view kKeyword = "none";
  static constexpr std::string_view kSummary = "no rolling resistance";
  static constexpr std::size_t kHistorySize = 0;
  static constexpr bool kReadsTangentialStiffness = false;
  static NoRolling from_material(const DemContactParameters&) { return {}; }
  Vec3 torque(const ContactInput&, const RollingLoad&, double*) const { return Vec3::Zero(); }
  double spring_stiffness(const ContactInput&, const RollingLoad&) const { return 0.0; }
};

template <bool kClamped>
class ConstantTorqueRolling {
 public:
  static constexpr std::string_view kKeyword = kClamped ? "cdt_clamped" : "cdt";
  static constexpr std::string_view kSummary =
      kClamped ? "constant torque capped so one step cannot reverse the rolling"
               : "constant directional torque (Zhou et al. 1999)";
  static constexpr std::size_t kHistorySize = 0;
  static constexpr bool kReadsTangentialStiffness = false;
  ConstantTorqueRolling() = default;
  explicit ConstantTorqueRolling(double rolling_friction) : mu_r_(rolling_friction) {}
  static ConstantTorqueRolling from_material(const DemContactParameters& p) {
    return ConstantTorqueRolling(p.rolling_friction);
  }

  Vec3 torque(const ContactInput& in, const RollingLoad& load, double*) const {
    const Vec3& w = in.relative_angular_velocity;
    const double w_norm = std::sqrt(squared_norm(w));  // contact_kinematics.hpp
    Vec3 w_t = w - dot(w, in.normal) * in.normal;
    double scale = mu_r_ * in.effective_radius * load.reference_force / w_norm;
    if constexpr (kClamped) {
      // |M| = scale |w_t| <= I_eff |w_t| / dt
      scale = std::min(scale, in.effective_inertia / in.dt);
    }
    // No torque without rotation; a select rather than a branch (the batch loop vectorises).
    return select(w_norm != 0.0, -scale * w_t, Vec3::Zero());
  }
  double spring_stiffness(const ContactInput&, const RollingLoad&) const { return 0.0; }

 private:
  double mu_r_ = 0.0;
};

using RollingCdt = ConstantTorqueRolling<false>;
using RollingCdtClamped = ConstantTorqueRolling<true>;

class RollingEpsd2 {
 public:
  static constexpr std::string_view kKeyword = "epsd2";
  static constexpr std::string_view kSummary =
      "elastic-plastic spring torque, k_r = k_t R*^2 (Wensrich & Katterfeld 2012)";
  static constexpr std::size_t kHistorySize = 3;
  // k_r comes from the tangential part's k_t, so the tangential part stays even at mu = 0.
  static constexpr bool kReadsTangentialStiffness = true;
  RollingEpsd2() = default;
  explicit RollingEpsd2(double rolling_friction) : mu_r_(rolling_friction) {}
  static RollingEpsd2 from_material(const DemContactParameters& p) {
    return RollingEpsd2(p.rolling_friction);
  }

  Vec3 torque(const ContactInput& in, const RollingLoad& load, double* history) const {
    Eigen::Map<Vec3> m(history);
    const Vec3& w = in.relative_angular_velocity;
    const Vec3 w_t = w - dot(w, in.normal) * in.normal;
    const double kr = spring_stiffness(in, load);
    m -= kr * in.dt * w_t;
    m -= dot(m, in.normal) * in.normal;  // stays in the contact plane as the contact turns [I]
    const double cap = mu_r_ * in.effective_radius * std::abs(load.normal_force);
    const double size = std::sqrt(squared_norm(m));
    if (size > cap) m *= cap / size;
    return m;
  }
  double spring_stiffness(const ContactInput& in, const RollingLoad& load) const {
    return load.tangential_stiffness * in.effective_radius * in.effective_radius;
  }

 private:
  double mu_r_ = 0.0;
};

}  // namespace feedflow
