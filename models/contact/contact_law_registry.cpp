#include "models/contact/contact_law_registry.hpp"

#include <array>
#include <vector>

#include "models/core/errors.hpp"

namespace feedflow {
namespace {

template <class List>
constexpr std::array<ContactPartEntry, List::kSize> rows(ContactSlot slot) {
  std::array<ContactPartEntry, List::kSize> r{};
  for (std::size_t i = 0; i < List::kSize; ++i)
    r[i] = {List::kKeywords[i], slot, i, List::kHistorySizes[i], List::kSummaries[i]};
  return r;
}

template <std::size_t... N>
constexpr auto concatenate(const std::array<ContactPartEntry, N>&... parts) {
  std::array<ContactPartEntry, (N + ...)> all{};
  std::size_t i = 0;
  ((void)[&] { for (const auto& p : parts) all[i++] = p; }(), ...);
  return all;
}

constexpr auto kParts = concatenate(
    rows<NormalParts>(ContactSlot::normal), rows<TangentialParts>(ContactSlot::tangential),
    rows<RollingParts>(ContactSlot::rolling), rows<CohesionParts>(ContactSlot::cohesion));

constexpr std::string_view slot_name(ContactSlot s) {
  switch (s) {
    case ContactSlot::normal: return "normal";
    case ContactSlot::tangential: return "tangential";
    case ContactSlot::rolling: return "rolling";
    case ContactSlot::cohesion: return "cohesion";
  }
  return "";
}

std::string joined(std::span<const std::string_view> keywords) {
  std::string s;
  for (std::string_view k : keywords) (s += s.empty() ? "" : ", ") += k;
  return s;
}

// The part named `keyword` in its slot's list; an empty keyword keeps `fallback`.
template <class List>
PartChoice<List> choose(ContactSlot slot, std::string_view keyword, PartChoice<List> fallback) {
  if (keyword.empty()) return fallback;
  if (const auto c = PartChoice<List>::named(keyword)) return *c;
  const std::string name(slot_name(slot));
  throw InputError("", "contact." + name,
                   "unknown " + name + " contact part '" + std::string(keyword) +
                       "'; known: " + joined(List::kKeywords));
}

// "hysteretic_nonlinear2, hysteretic_nonlinear1": the normal parts with a cohesion branch.
template <class... Parts>
std::string with_cohesion_branch(PartList<Parts...>) {
  std::vector<std::string_view> keywords;
  ((Parts::kHasCohesionBranch ? keywords.push_back(Parts::kKeyword) : void()), ...);
  return joined(keywords);
}

}  // namespace

std::span<const ContactPartEntry> contact_parts() { return kParts; }

ContactLawChoice choose_contact_law(std::string_view normal, std::string_view tangential,
                                    std::string_view rolling, std::string_view cohesion) {
  ContactLawChoice c;
  c.normal = choose(ContactSlot::normal, normal, c.normal);
  c.tangential = choose(ContactSlot::tangential, tangential, c.tangential);
  c.rolling = choose(ContactSlot::rolling, rolling, c.rolling);
  c.cohesion = choose(ContactSlot::cohesion, cohesion, c.cohesion);
  const bool has_branch =
      c.normal.visit([](auto n) { return decltype(n)::type::kHasCohesionBranch; });
  const bool needs_branch =
      c.cohesion.visit([](auto k) { return decltype(k)::type::kNeedsCohesionBranch; });
  if (needs_branch && !has_branch) {
    throw InputError("", "contact.cohesion",
                     std::string(c.cohesion.keyword()) + " cohesion is the normal law's K_nc "
                     "branch; '" + std::string(c.normal.keyword()) + "' has none (laws with one: " +
                         with_cohesion_branch(NormalParts{}) + ")");
  }
  return c;
}

std::string contact_law_name(const ContactLawChoice& c) {
  std::string s(c.normal.keyword());
  for (std::string_view k : {c.tangential.keyword(), c.rolling.keyword(), c.cohesion.keyword()})
    (s += " + ") += k;
  return s;
}

}  // namespace feedflow
