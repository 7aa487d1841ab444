#include "designer/calibrate/calibration_report.hpp"

#include <algorithm>
#include <sstream>

#include "designer/calibrate/discharge_fit.hpp"
#include "models/units/angle.hpp"
#include "models/units/quantity_format.hpp"

namespace feedflow {
namespace {

std::size_t fitted_count(const CalibrationOutcome& o) {
  return static_cast<std::size_t>(std::count_if(o.observations.begin(), o.observations.end(),
                                                [](const DischargeObservation& x) { return !x.held_out; }));
}

nlohmann::ordered_json coefficients_json(const DischargeModel& row, const std::vector<double>& c) {
  nlohmann::ordered_json j = nlohmann::ordered_json::object();
  for (std::size_t i = 0; i < row.coefficients.size(); ++i) j[std::string(row.coefficients[i].name)] = c[i];
  return j;
}

}  // namespace

std::string rung_text(const CalibrationDesign& d) {
  if (d.against == "dem") return "L3 DEM at the case's resolution";
  std::string levels;
  for (std::size_t k = 0; k < d.cells_across.size(); ++k)
    levels += (k == 0 ? "" : k + 1 == d.cells_across.size() ? " and " : ", ") + format_number(d.cells_across[k], 3);
  std::string s = "L2 CEL-FEM, " + levels + " cells across the half outlet";
  if (d.cells_across.size() == 2)
    s += ", Richardson with order " + format_number(d.order.value_or(measured_hopper_rate_order().order), 3);
  else if (d.cells_across.size() > 2)
    s += ", Richardson with the observed order";
  return s;
}

std::string commit_text(const std::string& program, const std::set<std::string>& run_commits) {
  if (run_commits.size() == 1 && *run_commits.begin() == program) return program;
  std::string runs;
  bool unrecorded = false;
  for (const auto& c : run_commits) {
    if (c.empty()) unrecorded = true;
    else runs += (runs.empty() ? "" : ", ") + c;
  }
  if (!runs.empty()) return program + " (runs made by " + runs + (unrecorded ? " and earlier builds" : "") + ")";
  if (unrecorded) return program + " (runs made by an earlier build that did not record its commit)";
  return program;
}

Calibration calibration_table(const CalibrationOutcome& o, const std::string& scene, bool wedge,
                              const std::string& density_model, const std::string& commit, const std::string& date) {
  Calibration c;
  c.against = o.design.against;
  c.rung = rung_text(o.design);
  c.scene = scene;
  c.geometry = wedge ? "wedge" : "conical";
  c.density_model = density_model;
  c.commit = commit;
  c.date = date;
  c.points = o.observations.size();
  const bool held_out = fitted_count(o) < o.observations.size();
  for (const auto& row : o.fit.rows) {
    if (!row.failure.empty()) continue;
    CalibratedModel m;
    for (std::size_t i = 0; i < row.after.size(); ++i) m.coefficients[std::string(row.row->coefficients[i].name)] = row.after[i];
    set_error_figures(m, {row.fit_rms_before, row.held_out_max_before},
                      {row.fit_rms_after, row.held_out_max_after}, held_out);
    for (std::size_t k = 0; k < row.held.size(); ++k) m.figures["held_" + std::to_string(k + 1)] = row.held[k];
    c.discharge[std::string(row.row->name)] = std::move(m);
  }
  return c;
}

std::vector<CalibrationPointRecord> calibration_point_records(const CalibrationOutcome& o) {
  std::vector<CalibrationPointRecord> records;
  for (std::size_t i = 0; i < o.observations.size(); ++i) {
    const auto& x = o.observations[i];
    records.push_back({x.hopper.outlet_width, x.hopper.semi_angle, x.reference, x.error_bar, x.held_out,
                       o.points[o.observed[i]].reference.source});
  }
  return records;
}

nlohmann::ordered_json calibration_json_head(const std::string& material,
                                             const std::string& against, const std::string& rung,
                                             const std::string& commit, const std::string& date,
                                             std::size_t runs_made, std::size_t runs_read_back) {
  return {{"feedflow_calibrate", material},
          {"against", against},
          {"rung", rung},
          {"commit", commit},
          {"date", date},
          {"runs_made", runs_made},
          {"runs_read_back", runs_read_back}};
}

nlohmann::ordered_json point_json(nlohmann::ordered_json setting, bool held_out,
                                  const CalibrationPoint& point) {
  setting["held_out"] = held_out;
  setting["status"] = point.status;
  const BenchReference& r = point.reference;
  if (r.value)
    setting["reference"] = {{"value", *r.value},
                            {"error_bar", r.error_bar.value_or(0.0)},
                            {"unit", r.unit},
                            {"source", r.source}};
  return setting;
}

nlohmann::ordered_json calibration_json(const CalibrationOutcome& o, const Calibration& table) {
  nlohmann::ordered_json j =
      calibration_json_head(o.material, table.against, table.rung, table.commit, table.date,
                            o.runs_made, o.runs_read_back);
  auto& jp = j["points"] = nlohmann::ordered_json::array();
  for (std::size_t i = 0; i < o.points.size(); ++i) {
    const DesignPoint& d = o.design.points[i];
    jp.push_back(point_json({{"outlet_width", {{"value", d.outlet_width}, {"unit", "m"}}},
                             {"semi_angle", {{"value", d.semi_angle}, {"unit", "rad"}}}},
                            d.held_out, o.points[i]));
  }
  auto& jr = j["models"] = nlohmann::ordered_json::array();
  for (const auto& row : o.fit.rows)
    jr.push_back({{"model", row.row->name},
                  {"before", coefficients_json(*row.row, row.before)},
                  {"after", coefficients_json(*row.row, row.after)},
                  {"standard_errors", coefficients_json(*row.row, row.standard_errors)},
                  {"fit_rms_error_before", row.fit_rms_before},
                  {"fit_rms_error_after", row.fit_rms_after},
                  {"held_out_max_error_before", row.held_out_max_before},
                  {"held_out_max_error_after", row.held_out_max_after},
                  {"rate_before", row.rate_before},
                  {"rate_after", row.rate_after},
                  {"held", row.held},
                  {"failure", row.failure}});
  j["design_check"] = {{"rate_before", o.fit.design_before},
                       {"rate_after", o.fit.design_after},
                       {"band_holds_reference_before", o.fit.band_holds_before},
                       {"band_holds_reference_after", o.fit.band_holds_after}};
  return j;
}

std::string calibration_summary(const CalibrationOutcome& o, const Calibration& table) {
  std::ostringstream s;
  const std::size_t fitted = fitted_count(o);
  s << "Discharge rate, " << o.material << ", against " << table.rung << " (" << o.observations.size() << " points, "
    << o.observations.size() - fitted << " held out):\n";
  for (std::size_t i = 0; i < o.observations.size(); ++i) {
    const auto& x = o.observations[i];
    s << "  W = " << format_number(x.hopper.outlet_width * 1e3, 4) << " mm, theta = "
      << format_number(in_degrees(x.hopper.semi_angle), 4) << " deg" << (x.held_out ? " (held out)" : "")
      << ": reference " << format_number(x.reference, 4) << " +- " << format_number(x.error_bar, 2)
      << " kg/s; design check " << format_number(o.fit.design_before[i], 4) << " -> "
      << format_number(o.fit.design_after[i], 4) << " kg/s, band holds it: " << (o.fit.band_holds_before[i] ? "yes" : "no")
      << " -> " << (o.fit.band_holds_after[i] ? "yes" : "no") << '\n';
  }
  for (const auto& row : o.fit.rows) {
    s << "  " << row.row->name << ": " << coefficients_text(*row.row, row.before) << " -> "
      << coefficients_text(*row.row, row.after) << "; rms error " << percent(row.fit_rms_before) << " -> "
      << percent(row.fit_rms_after);
    if (fitted < o.observations.size())
      s << ", held-out max " << percent(row.held_out_max_before) << " -> " << percent(row.held_out_max_after);
    for (const auto& h : row.held) s << " (" << h << ")";
    if (!row.failure.empty()) s << " (not fitted: " << row.failure << ")";
    s << '\n';
  }
  for (std::size_t i = 0; i < o.points.size(); ++i)
    if (o.points[i].status != "done") s << "  " << o.points[i].question.title << ": left out, " << o.points[i].status << '\n';
  return s.str();
}

}  // namespace feedflow
