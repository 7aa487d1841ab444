#pragma once
// A contact law composed at compile time of a normal, a tangential, a rolling and a cohesion
// part (MercuryDPM-style composition, LAMMPS-style sub-model slots): the pair loop calls one
// inline kernel, no virtual call. Each part owns a fixed run of history slots; the law's
// history is one std::array<double, kHistorySize> per contact, laid out
// [normal | tangential | rolling], zeroed when the contact opens.
//
//   ContactLaw<HystereticNonlinear2, TangentialHistory<HandedOnStiffness>, RollingCdt,
//              NoCohesion> law(material.dem.particle_particle);
//   ContactLaw<...>::History h{};          // beside the neighbour entry
//   ContactOutput out = law.evaluate(input, h);
#include <array>
#include <cstddef>
#include <string>

#include "models/contact/cohesion.hpp"
#include "models/contact/contact_kinematics.hpp"
#include "models/contact/normal_response.hpp"
#include "models/contact/rolling_resistance.hpp"
#include "models/contact/tangential_history.hpp"
#include "models/material/dem_parameters.hpp"

namespace feedflow {

template <class Normal, class Tangential, class Rolling, class Cohesion = NoCohesion>
class ContactLaw {
  static_assert(Normal::kHasCohesionBranch || !Cohesion::kNeedsCohesionBranch,
                "this normal law has no cohesion branch");

 public:
  using NormalPart = Normal;
  using TangentialPart = Tangential;
  using RollingPart = Rolling;
  using CohesionPart = Cohesion;
  static constexpr std::size_t kNormalOffset = 0;
  static constexpr std::size_t kTangentialOffset = kNormalOffset + Normal::kHistorySize;
  static constexpr std::size_t kRollingOffset = kTangentialOffset + Tangential::kHistorySize;
  static constexpr std::size_t kHistorySize = kRollingOffset + Rolling::kHistorySize;
  using History = std::array<double, kHistorySize>;
  // The first history slot is non-zero after any evaluation of a touching contact (until it
  // opens and the history is zeroed), so one look tells a used history from a cleared one.
  static constexpr bool kFirstSlotMarksUse = [] {
    if constexpr (requires { Normal::kFirstSlotMarksUse; })
      return Normal::kFirstSlotMarksUse;
    else
      return false;
  }();

  ContactLaw() = default;
  ContactLaw(Normal normal, Tangential tangential, Rolling rolling, Cohesion cohesion = {})
      : normal_(acting(normal)), tangential_(tangential), rolling_(rolling), cohesion_(cohesion) {}
  // Each part takes its values from one Table 2 column (P-P or P-W).
  explicit ContactLaw(const DemContactParameters& p)
      : normal_(acting(Normal::from_material(p))),
        tangential_(Tangential::from_material(p)),
        rolling_(Rolling::from_material(p)),
        cohesion_(Cohesion::from_material(p)) {}

  // "hysteretic_nonlinear2 + history + cdt + none"
  static std::string name() {
    std::string s(Normal::kKeyword);
    for (auto k : {Tangential::kKeyword, Rolling::kKeyword, Cohesion::kKeyword})
      (s += " + ") += k;
    return s;
  }

  // The per-contact kernel. A contact with overlap <= 0 is open: its history is zeroed and it
  // exerts nothing.
  ContactOutput evaluate(const ContactInput& in, History& h) const {
    if (!(in.overlap > 0.0)) {
      h.fill(0.0);
      return {};
    }
    return evaluate_touching(in, h);
  }
  // The kernel of a contact known to be closed (overlap > 0), without a branch of its own (the
  // pair loop's batches run it over many contacts as one vector loop). The responses are not
  // const: g++ keeps a const local aggregate in memory, which stops the loop vectorising.
  ContactOutput evaluate_touching(const ContactInput& in, History& h) const {
    NormalResponse n = normal_.respond(in, h.data() + kNormalOffset);
    const double fn = Cohesion::normal_force(n.force);
    TangentialResponse t = tangential_.respond(in, fn, n, h.data() + kTangentialOffset);
    const RollingLoad load = rolling_load(n, fn, t.stiffness);
    return {fn, t.force, rolling_.torque(in, load, h.data() + kRollingOffset)};
  }

  // The stiffest springs of this contact if it were evaluated now (history left unchanged).
  ContactStiffness stiffness(const ContactInput& in, const History& h) const {
    if (!(in.overlap > 0.0)) return {};
    History copy = h;
    const NormalResponse n = normal_.respond(in, copy.data() + kNormalOffset);
    const double fn = Cohesion::normal_force(n.force);
    const TangentialResponse t = tangential_.respond(in, fn, n, copy.data() + kTangentialOffset);
    const RollingLoad load = rolling_load(n, fn, t.stiffness);
    return {normal_.spring_stiffness(in, copy.data() + kNormalOffset),
            tangential_.spring_stiffness(in, n), rolling_.spring_stiffness(in, load)};
  }

  const Normal& normal() const { return normal_; }
  const Tangential& tangential() const { return tangential_; }
  const Rolling& rolling() const { return rolling_; }

 private:
  // The normal part as the cohesion part lets it act (a law with a cohesion branch may pull
  // further below delta0 when contacts may pull at all).
  static Normal acting(const Normal& n) {
    if constexpr (Cohesion::kNeedsCohesionBranch)
      return n.cohesive();
    else
      return n;
  }
  static RollingLoad rolling_load(const NormalResponse& n, double fn, double kt) {
    const double ref = Normal::kRollingOnTotalForce ? fn : n.elastic_force;
    return {ref > 0.0 ? ref : 0.0, fn, kt};
  }
  Normal normal_;
  Tangential tangential_;
  Rolling rolling_;
  [[no_unique_address]] Cohesion cohesion_;
};

}  // namespace feedflow
