#include "designer/calibrate/drum_calibration_report.hpp"

#include <algorithm>
#include <sstream>

#include "designer/calibrate/discharge_fit.hpp"
#include "models/units/angle.hpp"
#include "models/units/quantity_format.hpp"

namespace feedflow {
namespace {

std::string degrees(double radians, int digits = 4) {
  return format_number(in_degrees(radians), digits);
}

std::string layer_text(double fraction, double shift) {
  return "c_delta " + format_number(fraction, 3) + ", friction shift " +
         format_quantity(shift, "deg", 3);
}

}  // namespace

std::string drum_rung_text(const DrumCalibrationOutcome& o) {
  if (o.design.against == "dem") return "L3 DEM, the seed's law on the seed's 3D drum";
  std::vector<double> cells;
  if (!o.points.empty())
    for (const auto& p : o.points.front().question.points)
      if (p.cell_size) cells.push_back(*p.cell_size);
  std::string levels;
  for (std::size_t k = 0; k < cells.size(); ++k)
    levels += (k == 0                  ? ""
               : k + 1 == cells.size() ? " and "
                                       : ", ") +
              format_number(cells[k] * 1e3, 3);
  return "L2 CEL-FEM, cells " + levels +
         " mm (the bench's refinement series of the drum's radius), " +
         (cells.size() >= 3 ? "Richardson with the observed order" : "Richardson");
}

DrumCalibration drum_calibration_table(const DrumCalibrationOutcome& o, const std::string& scene,
                                       const Drum& scene_drum, const std::string& commit,
                                       const std::string& date) {
  DrumCalibration c;
  c.against = o.design.against;
  c.rung = drum_rung_text(o);
  c.scene = scene;
  c.end_walls = o.design.against == "dem";
  c.diameter = scene_drum.diameter;
  c.fill_fraction = scene_drum.fill_fraction;
  c.commit = commit;
  c.date = date;
  c.layer = o.fit.layer;
  c.points = o.observations.size();
  return c;
}

std::vector<DrumPointRecord> drum_point_records(const DrumCalibrationOutcome& o) {
  std::vector<DrumPointRecord> records;
  for (std::size_t i = 0; i < o.observations.size(); ++i) {
    const auto& x = o.observations[i];
    records.push_back({x.drum.speed, x.reference, x.error_bar, x.held_out,
                       o.points[o.observed[i]].reference.source});
  }
  return records;
}

nlohmann::ordered_json drum_calibration_json(const DrumCalibrationOutcome& o,
                                             const DrumCalibration& table) {
  nlohmann::ordered_json j =
      calibration_json_head(o.material, table.against, table.rung, table.commit, table.date,
                            o.runs_made, o.runs_read_back);
  j["scene"] = "drum";
  auto& jp = j["points"] = nlohmann::ordered_json::array();
  for (std::size_t i = 0; i < o.points.size(); ++i) {
    const DrumDesignPoint& d = o.design.points[i];
    jp.push_back(
        point_json({{"speed", {{"value", d.speed}, {"unit", "rad/s"}}}}, d.held_out, o.points[i]));
  }
  const DrumLayerFit& f = o.fit;
  j["flowing_layer"] = {
      {"layer_fraction_before", f.layer_fraction_before},
      {"layer_fraction_after", f.layer_fraction_after},
      {"layer_fraction_standard_error", f.layer_fraction_error},
      {"friction_shift_before", {{"value", f.shift_before}, {"unit", "rad"}}},
      {"friction_shift_after", {{"value", f.shift_after}, {"unit", "rad"}}},
      {"friction_shift_standard_error", {{"value", f.shift_error}, {"unit", "rad"}}},
      {"fit_rms_error_before", f.fit_rms_before},
      {"fit_rms_error_after", f.fit_rms_after},
      {"held_out_max_error_before", f.held_out_max_before},
      {"held_out_max_error_after", f.held_out_max_after},
      {"held", f.held},
      {"failure", f.failure}};
  j["design_check"] = {{"angle_before", {{"value", f.angle_before}, {"unit", "rad"}}},
                       {"angle_after", {{"value", f.angle_after}, {"unit", "rad"}}},
                       {"band_holds_reference_before", f.band_holds_before},
                       {"band_holds_reference_after", f.band_holds_after}};
  return j;
}

std::string drum_calibration_summary(const DrumCalibrationOutcome& o,
                                     const DrumCalibration& table) {
  std::ostringstream s;
  const auto held =
      static_cast<std::size_t>(std::count_if(o.observations.begin(), o.observations.end(),
                                             [](const DrumObservation& x) { return x.held_out; }));
  const DrumLayerFit& f = o.fit;
  s << "Drum angle of repose, " << o.material << ", against " << table.rung << " ("
    << o.observations.size() << " speeds, " << held << " held out"
    << (table.end_walls ? "" : "; the slice has no end walls, nor has the fit") << "):\n";
  for (std::size_t i = 0; i < o.observations.size(); ++i) {
    const auto& x = o.observations[i];
    s << "  " << format_number(in_rpm(x.drum.speed), 4) << " rpm"
      << (x.held_out ? " (held out)" : "") << ": reference " << degrees(x.reference) << " +- "
      << degrees(x.error_bar, 2) << " deg; design check " << degrees(f.angle_before[i]) << " -> "
      << degrees(f.angle_after[i])
      << " deg, band holds it: " << (f.band_holds_before[i] ? "yes" : "no") << " -> "
      << (f.band_holds_after[i] ? "yes" : "no") << '\n';
  }
  s << "  flowing layer: " << layer_text(f.layer_fraction_before, f.shift_before) << " -> "
    << layer_text(f.layer_fraction_after, f.shift_after) << "; rms error "
    << percent(f.fit_rms_before) << " -> " << percent(f.fit_rms_after);
  if (held)
    s << ", held-out max " << percent(f.held_out_max_before) << " -> "
      << percent(f.held_out_max_after);
  if (!f.held.empty()) s << " (" << f.held << ")";
  if (!f.failure.empty()) s << " (not fitted: " << f.failure << ")";
  s << '\n';
  for (std::size_t i = 0; i < o.points.size(); ++i)
    if (o.points[i].status != "done")
      s << "  " << o.points[i].question.title << ": left out, " << o.points[i].status << '\n';
  return s.str();
}

}  // namespace feedflow
