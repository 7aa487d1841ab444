#pragma once
// Declarative description of the fields of an input record (a hopper, a material section, ...):
// key, dimension, unit shown to people, valid range, and where the value lives. The case-file
// loader (designer/), the `materials` listing and the reports all read these tables, so a field
// is described once.
#include <limits>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "models/units/dimension.hpp"

namespace feedflow {

// A closed, open or half-open interval; infinite ends mean "no bound".
struct Range {
  double lower = -std::numeric_limits<double>::infinity();
  double upper = std::numeric_limits<double>::infinity();
  bool lower_inclusive = true;
  bool upper_inclusive = true;

  static Range positive() { return {0.0, std::numeric_limits<double>::infinity(), false, true}; }
  static Range non_negative() { return {0.0, std::numeric_limits<double>::infinity(), true, true}; }
  static Range open(double lo, double hi) { return {lo, hi, false, false}; }
  static Range closed(double lo, double hi) { return {lo, hi, true, true}; }
  static Range half_open(double lo, double hi) { return {lo, hi, true, false}; }  // [lo, hi)

  bool contains(double x) const {
    const bool above = lower_inclusive ? x >= lower : x > lower;
    const bool below = upper_inclusive ? x <= upper : x < upper;
    return above && below;
  }
  // "must be > 0 deg and < 90 deg", with the bounds in `unit`.
  std::string describe(std::string_view unit) const;
};

enum class Presence { required, optional };

template <class Record>
struct FieldSpec {
  std::string_view key;          // key inside its table, e.g. "semi_angle"
  std::string_view description;  // one line for listings and reports
  Presence presence = Presence::required;

  // Number fields: dimension, unit for people, range, and the member (plain or optional).
  Dimension dimension{};
  std::string_view display_unit;
  Range range{};
  double Record::*number = nullptr;
  std::optional<double> Record::*optional_number = nullptr;
  bool whole = false;  // a count or a seed: no fraction

  // List fields: several numbers of one dimension (a measured table).
  std::vector<double> Record::*number_list = nullptr;

  // Label fields: the allowed words and the member.
  std::span<const std::string_view> choices{};
  std::string Record::*label = nullptr;

  bool is_label() const { return label != nullptr; }
};

// Convenience constructors keep the tables in models/ short and readable.
template <class Record>
constexpr FieldSpec<Record> number_field(std::string_view key, double Record::*member,
                                         Dimension dimension, std::string_view display_unit,
                                         Range range, std::string_view description,
                                         Presence presence = Presence::required) {
  FieldSpec<Record> f;
  f.key = key;
  f.description = description;
  f.presence = presence;
  f.dimension = dimension;
  f.display_unit = display_unit;
  f.range = range;
  f.number = member;
  return f;
}

template <class Record>
constexpr FieldSpec<Record> optional_number_field(std::string_view key,
                                                  std::optional<double> Record::*member,
                                                  Dimension dimension,
                                                  std::string_view display_unit, Range range,
                                                  std::string_view description) {
  FieldSpec<Record> f;
  f.key = key;
  f.description = description;
  f.presence = Presence::optional;
  f.dimension = dimension;
  f.display_unit = display_unit;
  f.range = range;
  f.optional_number = member;
  return f;
}

template <class Record>
constexpr FieldSpec<Record> number_list_field(std::string_view key,
                                              std::vector<double> Record::*member,
                                              Dimension dimension, std::string_view display_unit,
                                              Range range, std::string_view description) {
  FieldSpec<Record> f;
  f.key = key;
  f.description = description;
  f.presence = Presence::optional;
  f.dimension = dimension;
  f.display_unit = display_unit;
  f.range = range;
  f.number_list = member;
  return f;
}

template <class Record>
constexpr FieldSpec<Record> label_field(std::string_view key, std::string Record::*member,
                                        std::span<const std::string_view> choices,
                                        std::string_view description,
                                        Presence presence = Presence::required) {
  FieldSpec<Record> f;
  f.key = key;
  f.description = description;
  f.presence = presence;
  f.choices = choices;
  f.label = member;
  return f;
}

// The same field, taking whole numbers only (a seed, a count).
template <class Record>
constexpr FieldSpec<Record> whole_number(FieldSpec<Record> f) {
  f.whole = true;
  return f;
}

// A problem found by a record's cross-field check: which key, and what is wrong.
struct FieldProblem {
  std::string key;      // key inside the record's table ("outlet_width")
  std::string message;  // "must be smaller than bin_width (600 mm)"
  bool is_error = true; // false: a warning the user should see, not a refusal
};

}  // namespace feedflow
