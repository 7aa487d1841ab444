#pragma once
// The contact registry: one type list per slot (LAMMPS GRANULAR's sub-model table, MercuryDPM's
// compile-time composition). The keyword table, the keyword lookup and its errors, the law's
// name and the dispatch from a run-time choice to the compile-time ContactLaw<N, T, R, C> are
// all generated from these lists; the caller instantiates its pair loop once per composition
// and the loop itself never dispatches.
//
// Adding a part is one class (kKeyword, kSummary, kHistorySize and the members of its slot, see
// the parts below) plus one entry in its slot's list. A normal part says whether it has a
// cohesion branch (kHasCohesionBranch), a cohesion part whether it needs one
// (kNeedsCohesionBranch). Besides the lists and the seed's defaults, no code names a part.
#include <cstddef>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <type_traits>

#include "models/contact/cohesion.hpp"
#include "models/contact/contact_law.hpp"
#include "models/contact/hertz_normal.hpp"
#include "models/contact/hooke_normal.hpp"
#include "models/contact/hysteretic_nonlinear1.hpp"
#include "models/contact/hysteretic_nonlinear2.hpp"
#include "models/contact/part_list.hpp"
#include "models/contact/rolling_resistance.hpp"
#include "models/contact/tangential_history.hpp"

namespace feedflow {

// --- the parts, one list per slot (the order is the table's) ---------------------------------
using NormalParts = PartList<HystereticNonlinear2, HystereticNonlinear1, HertzNormal, HookeNormal>;
using TangentialParts = PartList<NoTangential, TangentialHistory<HandedOnStiffness>,
                                 TangentialHistory<MindlinStiffness>>;
using RollingParts = PartList<NoRolling, RollingCdt, RollingCdtClamped, RollingEpsd2>;
using CohesionParts = PartList<NoCohesion, KncCohesion>;

static_assert(NormalParts::keywords_unique(), "two normal parts share a keyword");
static_assert(TangentialParts::keywords_unique(), "two tangential parts share a keyword");
static_assert(RollingParts::keywords_unique(), "two rolling parts share a keyword");
static_assert(CohesionParts::keywords_unique(), "two cohesion parts share a keyword");

enum class ContactSlot { normal, tangential, rolling, cohesion };

namespace contact_registry_detail {
template <class Part>
constexpr auto choice_of() {
  static_assert(NormalParts::contains<Part>() + TangentialParts::contains<Part>() +
                        RollingParts::contains<Part>() + CohesionParts::contains<Part>() ==
                    1,
                "a contact part is in exactly one slot's list");
  if constexpr (NormalParts::contains<Part>())
    return PartChoice<NormalParts>::of<Part>();
  else if constexpr (TangentialParts::contains<Part>())
    return PartChoice<TangentialParts>::of<Part>();
  else if constexpr (RollingParts::contains<Part>())
    return PartChoice<RollingParts>::of<Part>();
  else
    return PartChoice<CohesionParts>::of<Part>();
}
}  // namespace contact_registry_detail

// The choice of one part in its slot: contact_part<RollingCdt> is a PartChoice<RollingParts>.
template <class Part>
inline constexpr auto contact_part = contact_registry_detail::choice_of<Part>();

// One part per slot. The defaults are the seed's pine law (seed Sec. 2.3, models.md 3-4).
struct ContactLawChoice {
  PartChoice<NormalParts> normal = contact_part<HystereticNonlinear2>;
  PartChoice<TangentialParts> tangential = contact_part<TangentialHistory<HandedOnStiffness>>;
  PartChoice<RollingParts> rolling = contact_part<RollingCdt>;
  PartChoice<CohesionParts> cohesion = contact_part<NoCohesion>;
  friend bool operator==(const ContactLawChoice&, const ContactLawChoice&) = default;
};

struct ContactPartEntry {
  std::string_view keyword;
  ContactSlot slot = ContactSlot::normal;
  std::size_t index = 0;          // position in its slot's list
  std::size_t history_slots = 0;  // doubles of per-contact history it owns
  std::string_view summary;
};

// The registry table, one row per part: the normal, tangential, rolling and cohesion lists in
// their order.
std::span<const ContactPartEntry> contact_parts();

// Keywords to a choice; an empty keyword keeps the slot's default (the seed's law). Throws
// InputError naming the slot and the known keywords for an unknown keyword, and for a cohesion
// part that needs a cohesion branch (k_nc) with a normal law that has none.
ContactLawChoice choose_contact_law(std::string_view normal, std::string_view tangential = {},
                                    std::string_view rolling = {},
                                    std::string_view cohesion = {});

// "hysteretic_nonlinear2 + history + cdt + none" (ContactLaw::name() of the composed law, which
// the DEM checkpoint stores).
std::string contact_law_name(const ContactLawChoice& choice);

// Calls f(std::type_identity<Law>{}) with the composed law type of `choice` and returns its
// result (every instantiation must return the same type). A choice that pairs a cohesion part
// needing a branch with a normal part without one (which choose_contact_law refuses) throws
// std::invalid_argument.
template <class F>
decltype(auto) with_contact_law(const ContactLawChoice& choice, F&& f);
// The same with the normal part fixed at compile time (choice.normal is not read), so that the
// compositions of one normal part can be compiled apart from the others'.
template <class Normal, class F>
decltype(auto) with_contact_law_of_normal(const ContactLawChoice& choice, F&& f);

// --- implementation of the dispatch ---------------------------------------------------------
namespace contact_registry_detail {

template <class N, class T, class R, class C, class F>
decltype(auto) compose(F& f) {
  if constexpr (N::kHasCohesionBranch || !C::kNeedsCohesionBranch) {
    return f(std::type_identity<ContactLaw<N, T, R, C>>{});
  } else {
    throw std::invalid_argument("contact law: the cohesion part '" + std::string(C::kKeyword) +
                                "' needs a cohesion branch, which '" +
                                std::string(N::kKeyword) + "' has not");
    // Not reached; gives this instantiation the return type of the others.
    return f(std::type_identity<ContactLaw<N, T, R, NoCohesion>>{});
  }
}

}  // namespace contact_registry_detail

template <class Normal, class F>
decltype(auto) with_contact_law_of_normal(const ContactLawChoice& c, F&& f) {
  return c.tangential.visit([&](auto tangential) -> decltype(auto) {
    return c.rolling.visit([&](auto rolling) -> decltype(auto) {
      return c.cohesion.visit([&](auto cohesion) -> decltype(auto) {
        return contact_registry_detail::compose<Normal, typename decltype(tangential)::type,
                                                typename decltype(rolling)::type,
                                                typename decltype(cohesion)::type>(f);
      });
    });
  });
}

template <class F>
decltype(auto) with_contact_law(const ContactLawChoice& c, F&& f) {
  return c.normal.visit([&](auto normal) -> decltype(auto) {
    return with_contact_law_of_normal<typename decltype(normal)::type>(c, f);
  });
}

}  // namespace feedflow
