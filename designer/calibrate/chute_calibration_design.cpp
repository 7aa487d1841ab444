#include "designer/calibrate/chute_calibration_design.hpp"

#include <algorithm>
#include <cmath>

#include "designer/bench/bench_table.hpp"
#include "models/core/errors.hpp"
#include "models/units/angle.hpp"
#include "models/units/quantity_format.hpp"
#include "models/units/quantity_parser.hpp"

namespace feedflow {

void ChuteCalibrationDesign::check() const {
  for (const auto& p : points) {
    const char* flag = p.held_out ? "--held-out" : "--angles";
    if (!(p.angle > 0.0 && p.angle < 90.0 * kDegree))
      throw InputError(flag, degrees_text(p.angle) + " deg",
                       "expected inclinations in (0, 90) deg");
    for (const auto& q : points)
      if (&q != &p && std::abs(q.angle - p.angle) < 1e-9)
        throw InputError(flag, degrees_text(p.angle) + " deg",
                         "each inclination once (fitted or held out)");
  }
  const auto fitted = std::count_if(points.begin(), points.end(),
                                    [](const ChuteDesignPoint& p) { return !p.held_out; });
  if (fitted < 2)
    throw InputError("--angles", std::to_string(fitted) + " inclination(s)",
                     "a chute calibration fits theta2 and L: it needs at least two fitted "
                     "inclinations");
  if (against == "cel" && !(finest_cell <= 10e-3 + 1e-12))
    throw InputError("--finest-cell", format_number(finest_cell * 1e3, 3) + " mm",
                     "at most 10 mm: the reference needs two CEL levels (20 and 10 mm)");
}

std::vector<ChuteDesignPoint> inclination_points(const std::vector<double>& angles,
                                                 const std::vector<double>& held_out) {
  std::vector<ChuteDesignPoint> out;
  for (double a : angles) out.push_back({a, false});
  for (double a : held_out) out.push_back({a, true});
  return out;
}

std::string degrees_text(double angle) { return format_number(in_degrees(angle), 6); }

BenchQuestion chute_point_question(const ChuteCalibrationDesign& d, const ChuteDesignPoint& point) {
  const std::string deg = degrees_text(point.angle);
  // The deposit is unknown before the runs: keep_resolving_levels checks each level afterwards.
  BenchQuestion q = chute_question("chute_deposit_" + deg + "deg",
                                   "Inclined plane at " + deg + " deg: deposit thickness mid-ramp" +
                                       (point.held_out ? " (held out)" : ""),
                                   d.case_file, {"chute.angle=" + deg + "deg"}, 0.0, 0);
  if (!d.material.empty()) q.sets.push_back("case.material=" + d.material);
  const bool dem = d.against == "dem";
  std::erase_if(q.points, [&](const BenchPoint& p) {
    if (dem) return p.role != ReferenceRole::dem_reference;
    // The refinement series (one setting per level): the variants name a remap or a flux.
    return p.solver != Solver::cel || p.setting.find(',') != std::string::npos ||
           *p.cell_size < d.finest_cell * (1.0 - 1e-9);
  });
  for (auto& p : q.points)
    if (p.solver == Solver::cel) {
      p.role = ReferenceRole::cel_refinement;
      p.resolution = "checked against the deposit it finds";
    }
  return q;
}

std::string keep_resolving_levels(BenchQuestion& q, const std::map<std::string, BenchRun>& runs) {
  const BenchQuestionTable table = tabulate(q, runs);
  std::size_t levels = 0, kept = 0, still_flowing = 0;
  std::string dropped;
  for (std::size_t i = 0; i < q.points.size(); ++i) {
    BenchPoint& p = q.points[i];
    if (p.role != ReferenceRole::cel_refinement || !p.cell_size) continue;
    ++levels;
    const BenchAnswer& a = table.answers[i];
    if (!a.value) continue;  // not run, or no answer: the reference has no use for it anyway
    if (a.at_rest && !*a.at_rest) {  // an upper bound: out of the reference anyway
      ++still_flowing;
      continue;
    }
    double deposit = *a.value;
    try {
      deposit *= parse_quantity_as("1 " + a.unit, dim::length, false);
    } catch (const std::invalid_argument&) {
      continue;  // not a length: left to the table to judge
    }
    p.resolution = format_number(deposit / *p.cell_size, 2) + " cells across the deposit it finds";
    if (deposit >= kReferenceCellsAcross * *p.cell_size) {
      ++kept;
      continue;
    }
    p.role = ReferenceRole::none;
    dropped += (dropped.empty() ? "" : ", ") + format_quantity(deposit, "mm", 3) + " on " +
               format_quantity(*p.cell_size, "mm", 3) + " cells";
  }
  if (levels == 0 || kept >= 2) return {};
  return "the deposit is resolved (" + format_number(kReferenceCellsAcross, 2) +
         " cells across) on " + std::to_string(kept) + " CEL level(s) at rest" +
         (dropped.empty() ? "" : " (" + dropped + ")") +
         (still_flowing ? ", " + std::to_string(still_flowing) + " still flowing at the end" : "") +
         ": a finer --finest-cell" + (still_flowing ? " or a longer run" : "");
}

}  // namespace feedflow
