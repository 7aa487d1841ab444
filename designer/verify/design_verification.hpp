#pragma once
// `--verify`: a design check's answers verified on a full rung, as `design --verify` and
// `sweep --verify` run it. A hopper's discharge rate on the continuum rung when asked (cel) or
// when its decision is inside its band (auto, planned from the shipped bench table by tolerance
// and budget); its arching on the particle rung (dem: at the outlet, and the critical width by
// bisection); a chute's stopping thickness on the particle rung (dem: a bisection on the
// thickness of periodic stopping layers); a drum's or a chute's answers from one simulation on
// the rung asked otherwise. Without a
// verification that runs, a MARGINAL verdict says which command would settle it. The runs are
// kept in their folder and read back when asked again.
#include <filesystem>
#include <ostream>
#include <string>
#include <vector>

#include "designer/case/case.hpp"
#include "models/core/design_record.hpp"

namespace feedflow {

struct VerificationRequest {
  std::string case_file;          // as typed: the commands it suggests name it
  std::vector<std::string> sets;  // --set KEY=VALUE, as typed
  std::string mode = "off";       // off | auto | cel | dem
  // As typed (InputError naming --budget, --tolerance, --width-tolerance or
  // --thickness-tolerance when one is needed and is no positive quantity).
  std::string budget = "10 min";
  std::string tolerance = "10%";
  std::string width_tolerance = "1 mm";
  std::string thickness_tolerance;  // empty: one DEM sphere diameter
  // --start-from: an earlier record of this hopper's or chute's `--verify dem` (results.json,
  // maybe of a search cut short); its bracket's runs answer without a run. Empty: none.
  std::filesystem::path start_from;
  std::filesystem::path runs;   // the folder of the verification's runs
  std::ostream* log = nullptr;  // the runs' plans and phases; null: silent
};

// Verifies `record` (the design check of `c`) in place. Returns false when Ctrl-C stopped the
// runs (those made are kept in `request.runs`).
bool verify_design(const VerificationRequest& request, const Case& c, DesignRecord& record);

}  // namespace feedflow
