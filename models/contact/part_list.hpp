#pragma once
// A compile-time list of the contact parts of one slot, and the run-time choice of one of them.
// Each part type carries its keyword (kKeyword), a one-line summary (kSummary) and its history
// size (kHistorySize); everything the registry knows about a part is read from these members.
//
//   using RollingParts = PartList<NoRolling, RollingCdt, RollingEpsd2>;
//   PartChoice<RollingParts> r = PartChoice<RollingParts>::of<RollingCdt>();
//   r.keyword();                                      // "cdt"
//   r.visit([](auto part) { using P = typename decltype(part)::type; ... });
#include <array>
#include <cstddef>
#include <optional>
#include <string_view>
#include <tuple>
#include <type_traits>

namespace feedflow {

template <class... Parts>
struct PartList {
  static constexpr std::size_t kSize = sizeof...(Parts);
  static_assert(kSize > 0, "a slot needs at least one part");
  static constexpr std::array<std::string_view, kSize> kKeywords{Parts::kKeyword...};
  static constexpr std::array<std::string_view, kSize> kSummaries{Parts::kSummary...};
  static constexpr std::array<std::size_t, kSize> kHistorySizes{Parts::kHistorySize...};

  // The part at position I.
  template <std::size_t I>
  using At = std::tuple_element_t<I, std::tuple<Parts...>>;

  template <class Part>
  static constexpr bool contains() {
    return (std::is_same_v<Part, Parts> || ...);
  }
  // Position of Part in the list (the list must contain it).
  template <class Part>
  static constexpr std::size_t index_of() {
    static_assert(contains<Part>(), "the part is not in this list");
    std::size_t i = 0;
    (void)((std::is_same_v<Part, Parts> ? true : (++i, false)) || ...);
    return i;
  }
  // Position of the part named `keyword`, if any.
  static constexpr std::optional<std::size_t> find(std::string_view keyword) {
    for (std::size_t i = 0; i < kSize; ++i)
      if (kKeywords[i] == keyword) return i;
    return std::nullopt;
  }
  static constexpr bool keywords_unique() {
    for (std::size_t i = 0; i < kSize; ++i)
      for (std::size_t j = i + 1; j < kSize; ++j)
        if (kKeywords[i] == kKeywords[j]) return false;
    return true;
  }
};

namespace part_list_detail {

// f(std::type_identity<Part i>{}); an index past the end takes the last part (PartChoice only
// holds indices inside its list).
template <class F, class Part, class... Rest>
decltype(auto) visit(std::size_t i, F& f, PartList<Part, Rest...>) {
  if constexpr (sizeof...(Rest) > 0) {
    if (i != 0) return visit(i - 1, f, PartList<Rest...>{});
  }
  return f(std::type_identity<Part>{});
}

}  // namespace part_list_detail

// One part of List, chosen at run time; visit() hands the chosen part's type to a generic
// callable, so the caller instantiates its code once per part.
template <class List>
class PartChoice {
 public:
  template <class Part>
  static constexpr PartChoice of() {
    return PartChoice(List::template index_of<Part>());
  }
  // The part named `keyword`, if the list has one.
  static constexpr std::optional<PartChoice> named(std::string_view keyword) {
    const auto i = List::find(keyword);
    if (!i) return std::nullopt;
    return PartChoice(*i);
  }

  template <class Part>
  constexpr bool is() const {
    return index_ == List::template index_of<Part>();
  }
  constexpr std::string_view keyword() const { return List::kKeywords[index_]; }
  friend constexpr bool operator==(PartChoice, PartChoice) = default;

  // f(std::type_identity<Part>{}) with the chosen part; every instantiation must return the
  // same type.
  template <class F>
  decltype(auto) visit(F&& f) const {
    return part_list_detail::visit(index_, f, List{});
  }

 private:
  explicit constexpr PartChoice(std::size_t index) : index_(index) {}
  std::size_t index_;
};

}  // namespace feedflow
