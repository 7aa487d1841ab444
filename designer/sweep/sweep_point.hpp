#pragma once
// One design point of a sweep: the request every point shares (the case parsed once, the fixed
// and varied values, the models; what to solve for) and a point's answer, from the design check
// on the reduced rungs in this process. A point whose values the case loader refuses (a
// semi-angle past the wall, an outlet wider than the bin) is kept with its reason.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "designer/case/case_loader.hpp"
#include "designer/case/material_library.hpp"
#include "designer/design/model_choices.hpp"
#include "designer/sweep/sweep_axis.hpp"
#include "designer/sweep/sweep_target.hpp"
#include "models/core/design_record.hpp"

namespace feedflow {

// `--solve-for KEY --target CONDITION`: at each point of the other axes, the value of `axis`
// where the target starts (or stops) being met, scanned on the axis values and bisected to
// `tolerance` (SI).
struct SweepSolve {
  SweepAxis axis;
  SweepTarget target;
  double tolerance = 0.0;
};

struct SweepRequest {
  ParsedCase parsed;               // the case file, parsed once
  std::vector<SetOverride> fixed;  // the --set values every point takes
  std::vector<SweepAxis> axes;     // the --vary keys, the first varying slowest
  ModelChoices models;
  MaterialLibrary materials{{}};
  std::optional<SweepSolve> solve;
  bool sampled = false;  // the axes hold one value per point (a Latin hypercube), not a grid
};

// What a solve found at one point.
struct SweepSolution {
  enum class Outcome {
    solved,          // the condition changes inside the range: `value` is its boundary
    met_everywhere,  // met at every scanned value: the boundary lies beyond the range
    never_met,       // met at no scanned value
  };
  Outcome outcome = Outcome::never_met;
  bool smallest = true;  // met at and above `value` (else at and below)
  double value = 0.0;    // SI: the meeting side of the final bracket (solved)
  std::string text;      // `value` in the axis unit
  double bracket_low = 0.0, bracket_high = 0.0;  // SI: the final bracket
  // A pass target: where MARGINAL begins (SI), the design band's other edge (the smallest outlet
  // that does not fail, below the smallest that passes).
  std::optional<double> marginal_from;
  int evaluations = 0;
  int crossings = 0;  // times the condition changed along the scan (1 for a clean boundary)
  // Beyond the boundary (or at the nearest scanned value when never met): the value there
  // (the axis unit), its verdict and the checks that set it.
  std::string beyond_text;
  VerdictStatus beyond_verdict = VerdictStatus::unknown;
  std::vector<std::string> beyond_governing;
  std::string beyond_reason;  // the governing finding in words
};

struct SweepPoint {
  std::vector<std::size_t> index;  // the value of each axis
  bool done = false;               // answered; else `error` says why not
  std::string error;
  VerdictStatus verdict = VerdictStatus::unknown;
  std::vector<std::string> governing;  // the quantities of the findings at the verdict's status
  std::string governing_reason;        // the first of those findings in words
  Estimates results;                   // without the model texts
  // The limits the judge held results against (quantity, limit in the result's unit).
  std::vector<std::pair<std::string, double>> limits;
  double wall_seconds = 0.0;
  std::string rung = "L0";       // "L0" for the design check (reduced rungs), L2 or L3 simulated
  std::filesystem::path folder;  // a simulated point's files, below the sweep's folder
  std::optional<SweepSolution> solution;  // with --solve-for: the verdict and results are at it
};

// The overrides of one point: the fixed ones, then each axis at its value.
std::vector<SetOverride> point_overrides(const SweepRequest& request,
                                         const std::vector<std::size_t>& index);

// Answers one set of overrides (never throws for the values: a refused point is `done = false`).
SweepPoint answer_overrides(const SweepRequest& request, const std::vector<SetOverride>& sets);

// Answers one point of the axes.
SweepPoint answer_point(const SweepRequest& request, const std::vector<std::size_t>& index);

}  // namespace feedflow
