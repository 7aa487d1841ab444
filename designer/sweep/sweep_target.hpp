#pragma once
// The condition `--solve-for` looks for (`--target`), and whether a design point meets it:
//   pass                     the verdict is PASS
//   not-fail                 the verdict is PASS or MARGINAL
//   mass_flow_rate>=5kg/s    a result at or above a value (also >, <=, <); `=` asks where the
//                            result crosses the value (met at or above it)
//   mass_flow_rate.low>=5kg/s  the same on the low (or .high) end of the result's band
//   flow_pattern=mass        a label result equal to a word (!= for not equal)
// The value's unit must measure what the result measures; both are checked against a design
// check of the case before the sweep starts (InputError naming --target).
#include <optional>
#include <string>

#include "models/core/design_record.hpp"

namespace feedflow {

struct SweepTarget {
  enum class Kind { verdict, number, label };
  enum class Compare { at_least, above, at_most, below, crosses, equal, not_equal };
  Kind kind = Kind::verdict;
  std::string text;  // as written, for messages
  // verdict: the worst status that meets it (pass, or marginal for not-fail)
  VerdictStatus worst_meeting = VerdictStatus::pass;
  // number or label: the result key, which end of its band ("" = its value), the comparison
  std::string quantity;
  std::string band_end;  // "", "low" or "high"
  Compare compare = Compare::at_least;
  double value = 0.0;        // number: in the result's unit once checked (SI before)
  std::string written_unit;  // number: the unit the value was written in ("" if none)
  std::string word;          // label

  // The condition in words: "passes", "has mass_flow_rate >= 5 kg/s".
  std::string describe() const;
};

// Parses the text after --target (InputError naming --target).
SweepTarget parse_sweep_target(const std::string& text);

// Checks the target against one design point's results (the result exists, is a number or a
// label as the target needs, and the value's unit measures what the result does) and converts
// the value into the result's unit. InputError naming --target, listing the results there are.
void check_sweep_target(SweepTarget& target, const Estimates& results);

// Whether a point with this verdict and these results meets the target; nullopt when the
// point has no such result (the model did not answer it there).
std::optional<bool> meets_target(const SweepTarget& target, VerdictStatus verdict,
                                 const Estimates& results);

// How far a point is from meeting the target (smaller is nearer), to say what the nearest end
// of a range that never meets it gives.
double distance_to_target(const SweepTarget& target, VerdictStatus verdict,
                          const Estimates& results);

}  // namespace feedflow
