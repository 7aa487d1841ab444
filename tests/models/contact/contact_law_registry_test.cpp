// The contact registry: its keyword table, lookup, names and dispatch are generated from the
// four part lists, and it keeps the keywords, defaults and law names of the former hand-written
// table (the DEM checkpoint stores the law's name).
#include <gtest/gtest.h>

#include <algorithm>
#include <stdexcept>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

#include "models/contact/contact_law_registry.hpp"
#include "models/core/errors.hpp"

namespace feedflow {
namespace {

// A list with two parts of one keyword is caught at compile time.
static_assert(!PartList<RollingCdt, RollingEpsd2, RollingCdt>::keywords_unique());
static_assert(PartList<RollingCdt, RollingEpsd2>::keywords_unique());
// contact_part<> knows each part's slot: a rolling part cannot be put in the normal slot.
static_assert(std::is_same_v<std::remove_cv_t<decltype(contact_part<RollingCdt>)>,
                             PartChoice<RollingParts>>);
static_assert(!std::is_assignable_v<PartChoice<NormalParts>&, PartChoice<RollingParts>>);

std::string join(std::span<const std::string_view> keywords) {
  std::string s;
  for (std::string_view k : keywords) (s += s.empty() ? "" : ", ") += k;
  return s;
}

template <class... Parts>
int without_branch(PartList<Parts...>) {
  return (int{!Parts::kHasCohesionBranch} + ...);
}
template <class... Parts>
int needing_branch(PartList<Parts...>) {
  return (int{Parts::kNeedsCohesionBranch} + ...);
}

// "hertz + history + cdt + none" -> {"hertz", "history", "cdt", "none"}
std::vector<std::string> keywords_of(const std::string& name) {
  std::vector<std::string> k;
  std::size_t at = 0;
  for (std::size_t plus; (plus = name.find(" + ", at)) != std::string::npos; at = plus + 3)
    k.push_back(name.substr(at, plus - at));
  k.push_back(name.substr(at));
  return k;
}

template <class... Parts>
void expect_rows_of(ContactSlot slot, PartList<Parts...> list) {
  (
      [&] {
        using Part = Parts;
        const auto rows = contact_parts();
        const auto n = std::count_if(rows.begin(), rows.end(), [&](const ContactPartEntry& e) {
          return e.slot == slot && e.keyword == Part::kKeyword;
        });
        ASSERT_EQ(n, 1) << Part::kKeyword;
        const ContactPartEntry& e = *std::find_if(rows.begin(), rows.end(), [&](const auto& r) {
          return r.slot == slot && r.keyword == Part::kKeyword;
        });
        EXPECT_EQ(e.index, decltype(list)::template index_of<Part>()) << Part::kKeyword;
        EXPECT_EQ(e.history_slots, Part::kHistorySize) << Part::kKeyword;
        EXPECT_EQ(e.summary, Part::kSummary) << Part::kKeyword;
        EXPECT_FALSE(e.summary.empty()) << Part::kKeyword;
      }(),
      ...);
}

// Every part of every list has exactly one row, with its own history size and summary, and
// the table has no other rows.
TEST(ContactLawRegistry, TableHasOneRowPerPartOfEachList) {
  expect_rows_of(ContactSlot::normal, NormalParts{});
  expect_rows_of(ContactSlot::tangential, TangentialParts{});
  expect_rows_of(ContactSlot::rolling, RollingParts{});
  expect_rows_of(ContactSlot::cohesion, CohesionParts{});
  EXPECT_EQ(contact_parts().size(), NormalParts::kSize + TangentialParts::kSize +
                                        RollingParts::kSize + CohesionParts::kSize);
}

// Every keyword of the former hand-written table is still there, in its slot, with its history
// size (case files and checkpoints name them).
TEST(ContactLawRegistry, KeepsEveryKeywordOfTheFormerTable) {
  struct Row {
    std::string_view keyword;
    ContactSlot slot;
    std::size_t history;
  };
  using S = ContactSlot;
  const std::vector<Row> former = {
      {"hysteretic_nonlinear2", S::normal, 10}, {"hysteretic_nonlinear1", S::normal, 10},
      {"hertz", S::normal, 0},       {"hooke", S::normal, 0},
      {"none", S::tangential, 0},    {"history", S::tangential, 3},
      {"mindlin", S::tangential, 3}, {"none", S::rolling, 0},
      {"cdt", S::rolling, 0},        {"cdt_clamped", S::rolling, 0},
      {"epsd2", S::rolling, 3},      {"none", S::cohesion, 0},
      {"k_nc", S::cohesion, 0}};
  const auto rows = contact_parts();
  for (const Row& f : former) {
    const auto row = std::find_if(rows.begin(), rows.end(), [&](const ContactPartEntry& e) {
      return e.slot == f.slot && e.keyword == f.keyword;
    });
    ASSERT_NE(row, rows.end()) << f.keyword;
    EXPECT_EQ(row->history_slots, f.history) << f.keyword;
  }
}

template <class List>
void expect_unknown_lists_the_keywords(int position, const std::string& slot) {
  std::string kw[4] = {"hysteretic_nonlinear2", "history", "cdt", "none"};
  kw[position] = "hertzian";
  try {
    choose_contact_law(kw[0], kw[1], kw[2], kw[3]);
    ADD_FAILURE() << "accepted an unknown " << slot << " part";
  } catch (const InputError& e) {
    EXPECT_EQ(e.key(), "contact." + slot);
    EXPECT_EQ(std::string(e.what()), "contact." + slot + ": unknown " + slot +
                                         " contact part 'hertzian'; known: " +
                                         join(List::kKeywords));
  }
}

// An unknown keyword is refused with the slot's name and exactly its list's keywords.
TEST(ContactLawRegistry, UnknownKeywordListsExactlyTheSlotsKeywords) {
  expect_unknown_lists_the_keywords<NormalParts>(0, "normal");
  expect_unknown_lists_the_keywords<TangentialParts>(1, "tangential");
  expect_unknown_lists_the_keywords<RollingParts>(2, "rolling");
  expect_unknown_lists_the_keywords<CohesionParts>(3, "cohesion");
  try {
    choose_contact_law("hertzian", "history", "cdt", "none");
    ADD_FAILURE() << "accepted 'hertzian'";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(
                  "known: hysteretic_nonlinear2, hysteretic_nonlinear1, hertz, hooke"),
              std::string::npos);
  }
}

// k_nc is refused with the laws without a cohesion branch (hertz, hooke), accepted with the
// hysteretic ones, and the message names the laws that have one.
TEST(ContactLawRegistry, KncNeedsANormalLawWithACohesionBranch) {
  for (const char* normal : {"hertz", "hooke"}) {
    try {
      choose_contact_law(normal, "history", "cdt", "k_nc");
      ADD_FAILURE() << "k_nc accepted with " << normal;
    } catch (const InputError& e) {
      EXPECT_EQ(e.key(), "contact.cohesion");
      EXPECT_NE(std::string(e.what()).find(std::string("'") + normal + "' has none"),
                std::string::npos);
      EXPECT_NE(std::string(e.what()).find("hysteretic_nonlinear2, hysteretic_nonlinear1"),
                std::string::npos);
    }
  }
  EXPECT_NO_THROW(choose_contact_law("hysteretic_nonlinear1", "history", "cdt", "k_nc"));
  EXPECT_NO_THROW(choose_contact_law("hysteretic_nonlinear2", "none", "none", "k_nc"));
  // A hand-made choice the registry would refuse is not silently composed without cohesion.
  ContactLawChoice bad;
  bad.normal = contact_part<HertzNormal>;
  bad.cohesion = contact_part<KncCohesion>;
  EXPECT_THROW(with_contact_law(bad, [](auto) { return 0; }), std::invalid_argument);
}

// Every composition the registry accepts (all but those pairing a cohesion part that needs a
// branch with a normal part without one) has the name of its composed law, which the
// checkpoint stores, and the name's keywords choose it again.
TEST(ContactLawRegistry, NameRoundTripsForEveryComposition) {
  int accepted = 0, refused = 0;
  for (std::string_view n : NormalParts::kKeywords)
    for (std::string_view t : TangentialParts::kKeywords)
      for (std::string_view r : RollingParts::kKeywords)
        for (std::string_view c : CohesionParts::kKeywords) {
          ContactLawChoice choice;
          try {
            choice = choose_contact_law(n, t, r, c);
          } catch (const InputError&) {
            ++refused;
            continue;
          }
          ++accepted;
          const std::string name = contact_law_name(choice);
          EXPECT_EQ(name, std::string(n) + " + " + std::string(t) + " + " + std::string(r) +
                              " + " + std::string(c));
          EXPECT_EQ(with_contact_law(choice, [](auto law) { return decltype(law)::type::name(); }),
                    name);
          const std::vector<std::string> k = keywords_of(name);
          ASSERT_EQ(k.size(), 4u);
          EXPECT_EQ(choose_contact_law(k[0], k[1], k[2], k[3]), choice) << name;
        }
  EXPECT_EQ(accepted + refused, NormalParts::kSize * TangentialParts::kSize *
                                    RollingParts::kSize * CohesionParts::kSize);
  EXPECT_EQ(refused, without_branch(NormalParts{}) * TangentialParts::kSize *
                         RollingParts::kSize * needing_branch(CohesionParts{}));
}

// The defaults are the seed's law; an empty keyword keeps its slot's default; the dispatch
// composes the chosen parts (hertz + mindlin + epsd2: 0 + 3 + 3 history slots).
TEST(ContactLawRegistry, DefaultsAreTheSeedsLawAndKeywordsChooseTheParts) {
  EXPECT_EQ(contact_law_name(ContactLawChoice{}), "hysteretic_nonlinear2 + history + cdt + none");
  EXPECT_EQ(choose_contact_law(""), ContactLawChoice{});
  EXPECT_EQ(contact_law_name(choose_contact_law("hertz")), "hertz + history + cdt + none");
  const auto c = choose_contact_law("hertz", "mindlin", "epsd2", "none");
  EXPECT_TRUE(c.normal.is<HertzNormal>());
  EXPECT_TRUE(c.tangential.is<TangentialHistory<MindlinStiffness>>());
  EXPECT_TRUE(c.rolling.is<RollingEpsd2>());
  EXPECT_EQ(c.cohesion, contact_part<NoCohesion>);
  const std::size_t slots =
      with_contact_law(c, [](auto law) { return decltype(law)::type::kHistorySize; });
  EXPECT_EQ(slots, 6u);
}

}  // namespace
}  // namespace feedflow
