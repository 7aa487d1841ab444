#include "designer/calibrate/chute_calibration_report.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "designer/calibrate/discharge_fit.hpp"
#include "models/units/angle.hpp"
#include "models/units/quantity_format.hpp"

namespace feedflow {
namespace {

std::string law_text(double theta1, double theta2, double length) {
  return "theta1 " + format_quantity(theta1, "deg", 4) + ", theta2 " +
         format_quantity(theta2, "deg", 4) + ", L " + format_quantity(length, "mm", 3);
}

// "+- 1.2 deg": a standard error, or "(exact: no spare point)" without one.
std::string standard_error(double error, const char* unit, double scale) {
  if (!std::isfinite(error)) return " (exact: no spare point)";
  return " +- " + format_number(error * scale, 2) + " " + unit;
}

}  // namespace

std::string chute_rung_text(const ChuteCalibrationOutcome& o) {
  if (!o.rung.empty()) return o.rung;
  if (o.design.against == "dem")
    return "L3 DEM, the seed's law in periodic stopping layers (h_stop bisected to one sphere)";
  return "L2 CEL-FEM, cells from 20 mm to " + format_quantity(o.design.finest_cell, "mm", 3) +
         " (the levels that put " + format_number(kReferenceCellsAcross, 2) +
         " cells across the deposit they find), Richardson";
}

ChuteCalibration chute_calibration_table(const ChuteCalibrationOutcome& o, const std::string& scene,
                                         const std::string& commit, const std::string& date) {
  ChuteCalibration c;
  c.against = o.design.against;
  c.rung = chute_rung_text(o);
  c.scene = scene;
  bool first = true;
  for (const auto& x : o.observations)
    if (!x.held_out) {
      c.lowest_angle = first ? x.angle : std::min(c.lowest_angle, x.angle);
      c.highest_angle = first ? x.angle : std::max(c.highest_angle, x.angle);
      first = false;
    }
  c.commit = commit;
  c.date = date;
  c.law = o.fit.law;
  c.points = o.observations.size();
  return c;
}

std::vector<ChutePointRecord> chute_point_records(const ChuteCalibrationOutcome& o) {
  std::vector<ChutePointRecord> records;
  for (std::size_t i = 0; i < o.observations.size(); ++i) {
    const auto& x = o.observations[i];
    records.push_back(
        {x.angle, x.reference, x.error_bar, x.held_out, o.points[o.observed[i]].reference.source});
  }
  return records;
}

nlohmann::ordered_json chute_calibration_json(const ChuteCalibrationOutcome& o,
                                              const ChuteCalibration& table) {
  nlohmann::ordered_json j =
      calibration_json_head(o.material, table.against, table.rung, table.commit, table.date,
                            o.runs_made, o.runs_read_back);
  j["scene"] = "chute";
  auto& jp = j["points"] = nlohmann::ordered_json::array();
  for (std::size_t i = 0; i < o.points.size(); ++i) {
    const ChuteDesignPoint& d = o.design.points[i];
    jp.push_back(
        point_json({{"angle", {{"value", d.angle}, {"unit", "rad"}}}}, d.held_out, o.points[i]));
  }
  const StopLawFit& f = o.fit;
  const auto finite_or_null = [](double x) {
    return std::isfinite(x) ? nlohmann::ordered_json(x) : nlohmann::ordered_json();
  };
  j["stopping_thickness_law"] = {
      {"theta1_fitted", f.theta1_fitted},
      {"theta1_before", {{"value", f.theta1_before}, {"unit", "rad"}}},
      {"theta1_after", {{"value", f.theta1_after}, {"unit", "rad"}}},
      {"theta1_standard_error",
       {{"value", f.theta1_fitted ? finite_or_null(f.theta1_error) : nlohmann::ordered_json()},
        {"unit", "rad"}}},
      {"theta2_before", {{"value", f.theta2_before}, {"unit", "rad"}}},
      {"theta2_after", {{"value", f.theta2_after}, {"unit", "rad"}}},
      {"theta2_standard_error", {{"value", finite_or_null(f.theta2_error)}, {"unit", "rad"}}},
      {"stop_length_before", {{"value", f.length_before}, {"unit", "m"}}},
      {"stop_length_after", {{"value", f.length_after}, {"unit", "m"}}},
      {"stop_length_standard_error", {{"value", finite_or_null(f.length_error)}, {"unit", "m"}}},
      {"fit_rms_error_before", f.fit_rms_before},
      {"fit_rms_error_after", f.fit_rms_after},
      {"held_out_max_error_before", f.held_out_max_before},
      {"held_out_max_error_after", f.held_out_max_after},
      {"failure", f.failure}};
  j["design_check"] = {
      {"stopping_thickness_before", {{"value", f.thickness_before}, {"unit", "m"}}},
      {"stopping_thickness_after", {{"value", f.thickness_after}, {"unit", "m"}}},
      {"band_holds_reference_before", f.band_holds_before},
      {"band_holds_reference_after", f.band_holds_after}};
  return j;
}

std::string chute_calibration_summary(const ChuteCalibrationOutcome& o,
                                      const ChuteCalibration& table) {
  std::ostringstream s;
  const auto held =
      static_cast<std::size_t>(std::count_if(o.observations.begin(), o.observations.end(),
                                             [](const StopObservation& x) { return x.held_out; }));
  const StopLawFit& f = o.fit;
  s << "Chute stopping thickness, " << o.material << ", against " << table.rung << " ("
    << o.observations.size() << " inclinations, " << held << " held out; theta1 "
    << (f.theta1_fitted ? std::string("fitted")
                        : "held at " + format_quantity(f.theta1_before, "deg", 4))
    << "):\n";
  for (std::size_t i = 0; i < o.observations.size(); ++i) {
    const auto& x = o.observations[i];
    s << "  " << format_quantity(x.angle, "deg", 4) << (x.held_out ? " (held out)" : "")
      << ": reference " << format_quantity(x.reference, "mm", 4) << " +- "
      << format_quantity(x.error_bar, "mm", 2) << "; design check "
      << format_quantity(f.thickness_before[i], "mm", 4) << " -> "
      << format_quantity(f.thickness_after[i], "mm", 4)
      << ", band holds it: " << (f.band_holds_before[i] ? "yes" : "no") << " -> "
      << (f.band_holds_after[i] ? "yes" : "no") << '\n';
  }
  s << "  law: " << law_text(f.theta1_before, f.theta2_before, f.length_before) << " -> "
    << law_text(f.theta1_after, f.theta2_after, f.length_after);
  if (f.failure.empty())
    s << " ("
      << (f.theta1_fitted ? "theta1" + standard_error(f.theta1_error, "deg", 1.0 / kDegree) + ", "
                          : std::string())
      << "theta2" << standard_error(f.theta2_error, "deg", 1.0 / kDegree) << ", L"
      << standard_error(f.length_error, "mm", 1e3) << ")";
  s << "; rms error " << percent(f.fit_rms_before) << " -> " << percent(f.fit_rms_after);
  if (held)
    s << ", held-out max " << percent(f.held_out_max_before) << " -> "
      << percent(f.held_out_max_after);
  if (!f.failure.empty()) s << " (not fitted: " << f.failure << ")";
  s << '\n';
  for (std::size_t i = 0; i < o.points.size(); ++i)
    if (o.points[i].status != "done")
      s << "  " << o.points[i].question.title << ": left out, " << o.points[i].status << '\n';
  return s.str();
}

}  // namespace feedflow
