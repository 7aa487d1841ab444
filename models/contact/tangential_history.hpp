#pragma once
// Tangential parts (models.md 4.2): `none`, and a history spring with a Coulomb cap whose
// stiffness is either handed on by the normal part (`history`: k_t = k1 for the hysteretic
// laws, the seed software's choice and the default; Mindlin for hertz; k_n for hooke) or the
// Mindlin no-slip stiffness from E and nu (`mindlin`: k_t = 8 G* sqrt(R* delta)).
// Per step: xi += v_t dt, xi loses its normal component (length not restored), F_t = -k_t xi;
// if k_t |xi| > mu |F_n| the force is scaled onto the cap and xi = -F_t / k_t (no dashpot while
// sliding), else F_t -= gamma_t v_t. History: the three components of xi.
#include <cmath>
#include <cstddef>
#include <string_view>

#include <Eigen/Core>

#include "models/contact/contact_kinematics.hpp"
#include "models/contact/normal_response.hpp"
#include "models/contact/restitution_damping.hpp"
#include "models/material/dem_parameters.hpp"

namespace feedflow {

struct TangentialResponse {
  Vec3 force = Vec3::Zero();  // on body i [N]
  double stiffness = 0.0;     // k_t used [N/m] (epsd2 rolling derives k_r from it)
};

class NoTangential {
 public:
  static constexpr std::string_view kKeyword = "none";
  static constexpr std::string_view kSummary = "no tangential force";
  static constexpr std::size_t kHistorySize = 0;
  static NoTangential from_material(const DemContactParameters&) { return {}; }
  TangentialResponse respond(const ContactInput&, double, const NormalResponse& n,
                             double*) const {
    return {Vec3::Zero(), n.tangential_stiffness};
  }
  double spring_stiffness(const ContactInput&, const NormalResponse&) const { return 0.0; }
};

// k_t and gamma_t as handed on by the normal part.
struct HandedOnStiffness {
  static constexpr std::string_view kKeyword = "history";
  static constexpr std::string_view kSummary =
      "history spring, k_t handed on by the normal law (k1), Coulomb cap";
  static HandedOnStiffness from_material(const DemContactParameters&) { return {}; }
  void operator()(const ContactInput&, const NormalResponse& n, double& kt, double& gt) const {
    kt = n.tangential_stiffness;
    gt = n.tangential_damping;
  }
};

// Mindlin no-slip: k_t = 8 G* sqrt(R* delta), gamma_t = c sqrt(k_t m*) with the Hertz c.
struct MindlinStiffness {
  static constexpr std::string_view kKeyword = "mindlin";
  static constexpr std::string_view kSummary =
      "history spring, Mindlin no-slip k_t = 8 G* sqrt(R* delta), Coulomb cap";
  double shear_modulus = 0.0;            // G* [Pa]
  double damping_coefficient = 0.0;      // c [-]
  static MindlinStiffness from_material(const DemContactParameters& p,
                                        HertzDampingForm form = HertzDampingForm::restitution_exact) {
    return {feedflow::effective_shear_modulus(p.youngs_modulus, p.poisson_ratio),
            hertz_damping_coefficient(p.restitution, form)};
  }
  void operator()(const ContactInput& in, const NormalResponse&, double& kt, double& gt) const {
    kt = 8.0 * shear_modulus * std::sqrt(in.effective_radius * in.overlap);
    gt = damping_coefficient * std::sqrt(kt * in.effective_mass);
  }
};

template <class Stiffness>
class TangentialHistory {
 public:
  static constexpr std::string_view kKeyword = Stiffness::kKeyword;
  static constexpr std::string_view kSummary = Stiffness::kSummary;
  static constexpr std::size_t kHistorySize = 3;

  TangentialHistory() = default;
  TangentialHistory(double friction, Stiffness stiffness)
      : friction_(friction), stiffness_(stiffness) {}
  static TangentialHistory from_material(const DemContactParameters& p) {
    return TangentialHistory(p.friction, Stiffness::from_material(p));
  }
  double friction() const { return friction_; }

  TangentialResponse respond(const ContactInput& in, double normal_force,
                             const NormalResponse& n, double* history) const {
    double kt = 0.0, gt = 0.0;
    stiffness_(in, n, kt, gt);
    Eigen::Map<Vec3> xi(history);
    xi += in.tangential_velocity * in.dt;
    xi -= dot(xi, in.normal) * in.normal;
    Vec3 spring = -kt * xi;  // not const (nor below): see ContactLaw::evaluate_touching
    const double cap = friction_ * std::abs(normal_force);
    const double trial = kt * std::sqrt(squared_norm(xi));  // contact_kinematics.hpp
    // Sliding scales the spring onto the cap and resets xi from it, sticking adds the dashpot;
    // written as selects, without branches, so that a batch of contacts runs as one vector loop.
    const bool sliding = trial > cap;
    Vec3 slid = spring * (sliding ? cap / trial : 1.0);
    Vec3 f = select(sliding, slid, spring - gt * in.tangential_velocity);
    xi = select(sliding, -slid / kt, xi);
    return {f, kt};
  }

  double spring_stiffness(const ContactInput& in, const NormalResponse& n) const {
    double kt = 0.0, gt = 0.0;
    stiffness_(in, n, kt, gt);
    return kt;
  }

 private:
  double friction_ = 0.0;
  Stiffness stiffness_;
};

}  // namespace feedflow
