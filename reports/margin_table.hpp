#pragma once
// The margin table that leads a verdict: one row per judged finding with a number and a limit
// (the check, the requirement, what was achieved with its band, the margin from the band's
// near edge to the limit, the status), and the governing check marked: the worst status, then
// the least margin. Whether a requirement is a floor or a ceiling follows from the judges' two
// rules (verdict_builder.hpp): a pass has its whole band on the good side of the limit, a
// marginal its value, a fail has the value on the wrong side.
#include <string>
#include <vector>

#include "models/core/design_record.hpp"

namespace feedflow {

struct MarginRow {
  std::string check;        // "critical outlet width"
  std::string requirement;  // "<= 50 mm"
  std::string achieved;     // "30.58 mm (20.48 .. 42.18 mm)"
  std::string margin;       // "+15.6 %": how far the band's near edge is inside the limit
  double relative_margin = 0.0;
  VerdictStatus status = VerdictStatus::unknown;
  bool governing = false;
};

std::vector<MarginRow> margin_table(const Verdict& verdict);

}  // namespace feedflow
