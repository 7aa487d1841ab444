#pragma once
// One `--vary KEY=RANGE` of a sweep: the case key and the values it takes, each kept as the text
// handed to the case loader ("17.5 deg") and as its SI value. Ranges (units on either end or
// both, or on the step):
//   15..40deg/5deg       from 15 to 40 deg in steps of 5 deg (the end kept when it falls on a step)
//   20..100mm:9          nine values evenly spaced, ends included
//   0.01..1mm:5log       five values evenly spaced in the logarithm
//   "0.2,0.3,0.5 m"      a list; a unit at the end applies to the items written without one
//   material=pine,spruce a list of words (labels, material names)
// A number without a unit for a key that has a dimension is refused (a bare 30 would be read
// as 30 rad); so are an unknown key, an empty range, a zero or backward step, and a count
// below 2 or above 100 000.
#include <optional>
#include <string>
#include <vector>

#include "models/units/dimension.hpp"

namespace feedflow {

struct SweepValue {
  std::string text;          // for the case loader: "17.5 deg", "wedge"
  std::optional<double> si;  // numbers only
};

struct SweepAxis {
  std::string key;       // as written: "hopper.semi_angle" ("material" means case.material)
  std::string case_key;  // the key in the case file: "hopper.semi_angle", "case.material"
  std::string unit;      // the unit values are shown in ("deg"); empty for words or pure numbers
  std::vector<SweepValue> values;
  // A range (A..B) spans an interval a sample may take any value of (SI); a list does not.
  struct Span {
    double low = 0.0, high = 0.0;
    bool log = false;
  };
  std::optional<Span> span;
  bool numeric() const { return !values.empty() && values.front().si.has_value(); }
};

// The dimension and unit a case key's value takes: a [hopper], [chute], [drum], [design], [dem]
// or [cel] number; nullopt for labels and keys this table does not know (materials: the case
// loader checks those).
struct CaseKeyKind {
  bool known = false;
  bool label = false;
  Dimension dimension{};
  std::string display_unit;
};
CaseKeyKind case_key_kind(const std::string& case_key);

// Parses "KEY=RANGE" (the text after `flag`); InputError naming the flag on any fault.
SweepAxis parse_sweep_axis(const std::string& text, const std::string& flag = "--vary");

// The SI value of one of the axis's unit (1 for pure numbers).
double axis_unit_si(const SweepAxis& axis);

// A value of a numeric axis from its SI value, written in the axis unit with `significant`
// digits ("37.25 mm").
SweepValue axis_value(const SweepAxis& axis, double si, int significant = 12);

}  // namespace feedflow
