#pragma once
// Run-time choice of a composed contact law by name (material or case keywords), LAMMPS-style:
// a checked-in table maps each keyword to a part of one slot; with_contact_law() turns a
// choice into the compile-time ContactLaw type, so the caller instantiates its pair loop once
// per law and the loop itself never dispatches. Adding a part is one class plus one row here
// and one case in the dispatch.
#include <span>
#include <string>
#include <string_view>
#include <type_traits>

#include "models/contact/cohesion.hpp"
#include "models/contact/contact_law.hpp"
#include "models/contact/hertz_normal.hpp"
#include "models/contact/hooke_normal.hpp"
#include "models/contact/hysteretic_nonlinear1.hpp"
#include "models/contact/hysteretic_nonlinear2.hpp"
#include "models/contact/rolling_resistance.hpp"
#include "models/contact/tangential_history.hpp"

namespace feedflow {

enum class ContactSlot { normal, tangential, rolling, cohesion };
enum class NormalLaw { hysteretic_nonlinear2, hysteretic_nonlinear1, hertz, hooke };
enum class TangentialLaw { none, history, mindlin };
enum class RollingLaw { none, cdt, cdt_clamped, epsd2 };
enum class CohesionLaw { none, k_nc };

// The defaults are the seed's pine law (seed Sec. 2.3, models.md 3-4).
struct ContactLawChoice {
  NormalLaw normal = NormalLaw::hysteretic_nonlinear2;
  TangentialLaw tangential = TangentialLaw::history;
  RollingLaw rolling = RollingLaw::cdt;
  CohesionLaw cohesion = CohesionLaw::none;
};

struct ContactPartEntry {
  std::string_view keyword;
  ContactSlot slot;
  int kind;              // the enum value of its slot
  int history_slots;     // doubles of per-contact history it owns
  std::string_view summary;
};

// The registry table, one row per part.
std::span<const ContactPartEntry> contact_parts();

// Keywords to a choice. Throws InputError naming the slot and the known keywords for an unknown
// keyword, and for k_nc cohesion with a normal law that has no cohesion branch.
ContactLawChoice choose_contact_law(std::string_view normal, std::string_view tangential,
                                    std::string_view rolling, std::string_view cohesion);

// "hysteretic_nonlinear2 + history + cdt + none"
std::string contact_law_name(const ContactLawChoice& choice);

// Calls f(std::type_identity<Law>{}) with the composed law type of `choice` and returns its
// result (every instantiation must return the same type).
template <class F>
decltype(auto) with_contact_law(const ContactLawChoice& choice, F&& f);

// --- implementation of the dispatch ---------------------------------------------------------
namespace contact_dispatch {

template <class N, class T, class R, class F>
decltype(auto) cohesion(const ContactLawChoice& c, F&& f) {
  if constexpr (N::kHasCohesionBranch) {
    if (c.cohesion == CohesionLaw::k_nc)
      return f(std::type_identity<ContactLaw<N, T, R, KncCohesion>>{});
  }
  return f(std::type_identity<ContactLaw<N, T, R, NoCohesion>>{});
}

template <class N, class T, class F>
decltype(auto) rolling(const ContactLawChoice& c, F&& f) {
  switch (c.rolling) {
    case RollingLaw::cdt: return cohesion<N, T, RollingCdt>(c, f);
    case RollingLaw::cdt_clamped: return cohesion<N, T, RollingCdtClamped>(c, f);
    case RollingLaw::epsd2: return cohesion<N, T, RollingEpsd2>(c, f);
    case RollingLaw::none: break;
  }
  return cohesion<N, T, NoRolling>(c, f);
}

template <class N, class F>
decltype(auto) tangential(const ContactLawChoice& c, F&& f) {
  switch (c.tangential) {
    case TangentialLaw::history: return rolling<N, TangentialHistory<HandedOnStiffness>>(c, f);
    case TangentialLaw::mindlin: return rolling<N, TangentialHistory<MindlinStiffness>>(c, f);
    case TangentialLaw::none: break;
  }
  return rolling<N, NoTangential>(c, f);
}

}  // namespace contact_dispatch

template <class F>
decltype(auto) with_contact_law(const ContactLawChoice& c, F&& f) {
  switch (c.normal) {
    case NormalLaw::hysteretic_nonlinear1:
      return contact_dispatch::tangential<HystereticNonlinear1>(c, f);
    case NormalLaw::hertz: return contact_dispatch::tangential<HertzNormal>(c, f);
    case NormalLaw::hooke: return contact_dispatch::tangential<HookeNormal>(c, f);
    case NormalLaw::hysteretic_nonlinear2: break;
  }
  return contact_dispatch::tangential<HystereticNonlinear2>(c, f);
}

}  // namespace feedflow
