#include "models/contact/contact_law_registry.hpp"

#include <array>

#include "models/core/errors.hpp"

namespace feedflow {
namespace {

constexpr int k(auto e) { return static_cast<int>(e); }

constexpr std::array kParts{
    ContactPartEntry{"hysteretic_nonlinear2", ContactSlot::normal,
                     k(NormalLaw::hysteretic_nonlinear2), 10,
                     "Chen 2022 hysteretic law, exponential unloading (seed Eq. 7)"},
    ContactPartEntry{"hysteretic_nonlinear1", ContactSlot::normal,
                     k(NormalLaw::hysteretic_nonlinear1), 10,
                     "Chen hysteretic law, linear unloading, K_nc cohesion branch"},
    ContactPartEntry{"hertz", ContactSlot::normal, k(NormalLaw::hertz), 0,
                     "Hertz spring, dashpot from the restitution"},
    ContactPartEntry{"hooke", ContactSlot::normal, k(NormalLaw::hooke), 0,
                     "linear spring-dashpot, dashpot from the restitution"},
    ContactPartEntry{"none", ContactSlot::tangential, k(TangentialLaw::none), 0,
                     "no tangential force"},
    ContactPartEntry{"history", ContactSlot::tangential, k(TangentialLaw::history), 3,
                     "history spring, k_t handed on by the normal law (k1), Coulomb cap"},
    ContactPartEntry{"mindlin", ContactSlot::tangential, k(TangentialLaw::mindlin), 3,
                     "history spring, Mindlin no-slip k_t = 8 G* sqrt(R* delta), Coulomb cap"},
    ContactPartEntry{"none", ContactSlot::rolling, k(RollingLaw::none), 0,
                     "no rolling resistance"},
    ContactPartEntry{"cdt", ContactSlot::rolling, k(RollingLaw::cdt), 0,
                     "constant directional torque (Zhou et al. 1999)"},
    ContactPartEntry{"cdt_clamped", ContactSlot::rolling, k(RollingLaw::cdt_clamped), 0,
                     "constant torque capped so one step cannot reverse the rolling"},
    ContactPartEntry{"epsd2", ContactSlot::rolling, k(RollingLaw::epsd2), 3,
                     "elastic-plastic spring torque, k_r = k_t R*^2 (Wensrich & Katterfeld 2012)"},
    ContactPartEntry{"none", ContactSlot::cohesion, k(CohesionLaw::none), 0,
                     "normal force clipped at zero (limitForce)"},
    ContactPartEntry{"k_nc", ContactSlot::cohesion, k(CohesionLaw::k_nc), 0,
                     "the hysteretic law's F = -K_nc A2 delta branch acts (no clipping)"},
};

constexpr std::string_view slot_name(ContactSlot s) {
  switch (s) {
    case ContactSlot::normal: return "normal";
    case ContactSlot::tangential: return "tangential";
    case ContactSlot::rolling: return "rolling";
    case ContactSlot::cohesion: return "cohesion";
  }
  return "";
}

int find(ContactSlot slot, std::string_view keyword) {
  std::string known;
  for (const auto& p : kParts) {
    if (p.slot != slot) continue;
    if (p.keyword == keyword) return p.kind;
    (known += known.empty() ? "" : ", ") += p.keyword;
  }
  throw InputError("", std::string("contact.") + std::string(slot_name(slot)),
                   "unknown " + std::string(slot_name(slot)) + " contact part '" +
                       std::string(keyword) + "'; known: " + known);
}

std::string_view keyword(ContactSlot slot, int kind) {
  for (const auto& p : kParts)
    if (p.slot == slot && p.kind == kind) return p.keyword;
  return "?";
}

}  // namespace

std::span<const ContactPartEntry> contact_parts() { return kParts; }

ContactLawChoice choose_contact_law(std::string_view normal, std::string_view tangential,
                                    std::string_view rolling, std::string_view cohesion) {
  ContactLawChoice c;
  c.normal = static_cast<NormalLaw>(find(ContactSlot::normal, normal));
  c.tangential = static_cast<TangentialLaw>(find(ContactSlot::tangential, tangential));
  c.rolling = static_cast<RollingLaw>(find(ContactSlot::rolling, rolling));
  c.cohesion = static_cast<CohesionLaw>(find(ContactSlot::cohesion, cohesion));
  const bool hysteretic = c.normal == NormalLaw::hysteretic_nonlinear1 ||
                          c.normal == NormalLaw::hysteretic_nonlinear2;
  if (c.cohesion == CohesionLaw::k_nc && !hysteretic)
    throw InputError("", "contact.cohesion",
                     "k_nc cohesion is the hysteretic laws' branch; '" + std::string(normal) +
                         "' has none");
  return c;
}

std::string contact_law_name(const ContactLawChoice& c) {
  std::string s(keyword(ContactSlot::normal, k(c.normal)));
  (s += " + ") += keyword(ContactSlot::tangential, k(c.tangential));
  (s += " + ") += keyword(ContactSlot::rolling, k(c.rolling));
  (s += " + ") += keyword(ContactSlot::cohesion, k(c.cohesion));
  return s;
}

}  // namespace feedflow

namespace feedflow {
// The table's history column agrees with the parts.
static_assert(HystereticNonlinear2::kHistorySize == 10 && HystereticNonlinear1::kHistorySize == 10);
static_assert(HertzNormal::kHistorySize == 0 && HookeNormal::kHistorySize == 0);
static_assert(TangentialHistory<HandedOnStiffness>::kHistorySize == 3);
static_assert(TangentialHistory<MindlinStiffness>::kHistorySize == 3);
static_assert(RollingEpsd2::kHistorySize == 3 && RollingCdt::kHistorySize == 0);
}  // namespace feedflow
