#include "designer/calibrate/drum_calibration_design.hpp"

#include <algorithm>

#include "models/core/errors.hpp"
#include "models/units/angle.hpp"
#include "models/units/quantity_format.hpp"

namespace feedflow {

void DrumCalibrationDesign::check() const {
  for (const auto& p : points)
    if (!(p.speed > 0.0))
      throw InputError(p.held_out ? "--held-out" : "--speeds",
                       format_number(in_rpm(p.speed), 4) + " rpm",
                       "expected drum speeds above 0 rpm");
  const auto fitted = std::count_if(points.begin(), points.end(),
                                    [](const DrumDesignPoint& p) { return !p.held_out; });
  if (fitted < 2)
    throw InputError(
        "--speeds", std::to_string(fitted) + " speed(s)",
        "a drum calibration fits two coefficients: it needs at least two fitted speeds");
  if (against == "cel" && !(finest_cell <= 10e-3 + 1e-12))
    throw InputError("--finest-cell", format_number(finest_cell * 1e3, 3) + " mm",
                     "at most 10 mm: the reference needs two CEL levels that resolve the drum's "
                     "radius (20 and 10 mm)");
}

std::vector<DrumDesignPoint> speed_points(const std::vector<double>& speeds,
                                          const std::vector<double>& held_out) {
  std::vector<DrumDesignPoint> out;
  for (double s : speeds) out.push_back({s, false});
  for (double s : held_out) out.push_back({s, true});
  return out;
}

std::string rpm_text(double speed) { return format_number(in_rpm(speed), 6); }

BenchQuestion drum_point_question(const DrumCalibrationDesign& d, const DrumDesignPoint& point) {
  BenchQuestion q = drum_question(rpm_text(point.speed), false);
  if (point.held_out) q.title += " (held out)";
  q.case_file = d.case_file;
  if (!d.material.empty()) q.sets.push_back("case.material=" + d.material);
  const ReferenceRole wanted =
      d.against == "dem" ? ReferenceRole::dem_reference : ReferenceRole::cel_refinement;
  std::erase_if(q.points, [&](const BenchPoint& p) {
    return p.role != wanted || (p.cell_size && *p.cell_size < d.finest_cell * (1.0 - 1e-9));
  });
  return q;
}

}  // namespace feedflow
