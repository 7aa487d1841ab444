#include "designer/calibrate/arching_report.hpp"

#include <sstream>

#include "designer/calibrate/calibration_report.hpp"
#include "models/units/angle.hpp"
#include "models/units/quantity_format.hpp"

namespace feedflow {
namespace {

std::string mm(double metres) { return format_number(metres * 1e3, 4) + " mm"; }

std::string range_text(const ArchingRowFit& f) {
  return f.scale_low <= f.scale_high
             ? format_number(f.scale_low, 3) + " .. " + format_number(f.scale_high, 3)
             : "none (no single scale holds every bracket)";
}

std::size_t held_out_count(const ArchingCalibrationOutcome& o) {
  std::size_t n = 0;
  for (const auto& r : o.records) n += r.observation.held_out;
  return n;
}

}  // namespace

ArchingCalibration arching_calibration_table(const ArchingCalibrationOutcome& o,
                                             const std::string& commit, const std::string& date) {
  ArchingCalibration t;
  t.against = o.against;
  t.rung = o.records.front().rung;
  t.scene = o.scene;
  t.geometry = o.records.front().observation.hopper.is_wedge() ? "wedge" : "conical";
  t.flow_factor = o.flow_factor;
  t.commit = commit;
  t.date = date;
  const bool any_held_out = held_out_count(o) > 0;
  for (const auto& f : o.fit) {
    CalibratedModel m;
    m.coefficients["strength_scale"] = f.scale;
    set_error_figures(m, {f.fit_rms_before, f.held_out_max_before},
                      {f.fit_rms_after, f.held_out_max_after}, any_held_out);
    m.figures["scale_range"] = range_text(f);
    m.figures["brackets_held"] = std::to_string(f.held_before) + " -> " +
                                 std::to_string(f.held_after) + " of " +
                                 std::to_string(o.records.size());
    t.rows[std::string(f.row->name)] = std::move(m);
  }
  t.points = o.records.size();
  return t;
}

std::vector<ArchingPointRecord> arching_point_records(const ArchingCalibrationOutcome& o) {
  std::vector<ArchingPointRecord> out;
  for (const auto& r : o.records)
    out.push_back({r.observation.hopper.semi_angle, *r.observation.hopper.wall_friction_angle,
                   r.observation.arches_at, r.observation.flows_at, r.observation.held_out,
                   r.file.string() + ": " + r.bracket});
  return out;
}

nlohmann::ordered_json arching_calibration_json(const ArchingCalibrationOutcome& o,
                                                const ArchingCalibration& t) {
  nlohmann::ordered_json j =
      calibration_json_head(o.material, t.against, t.rung, t.commit, t.date, 0, o.records.size());
  j["quantity"] = "critical_outlet_width";
  j["flow_factor"] = t.flow_factor;
  auto& jp = j["points"] = nlohmann::ordered_json::array();
  for (const auto& r : o.records)
    jp.push_back({{"record", r.file.string()},
                  {"semi_angle", {{"value", r.observation.hopper.semi_angle}, {"unit", "rad"}}},
                  {"wall_friction_angle",
                   {{"value", *r.observation.hopper.wall_friction_angle}, {"unit", "rad"}}},
                  {"arches_at", {{"value", r.observation.arches_at}, {"unit", "m"}}},
                  {"flows_at", {{"value", r.observation.flows_at}, {"unit", "m"}}},
                  {"reference", {{"value", r.observation.reference()}, {"unit", "m"}}},
                  {"held_out", r.observation.held_out}});
  auto& jr = j["models"] = nlohmann::ordered_json::array();
  for (const auto& f : o.fit)
    jr.push_back({{"model", f.row->name},
                  {"strength_scale", f.scale},
                  {"scale_low", f.scale_low},
                  {"scale_high", f.scale_high},
                  {"critical_outlet_width_before", f.width_before},
                  {"critical_outlet_width_after", f.width_after},
                  {"fit_rms_error_before", f.fit_rms_before},
                  {"fit_rms_error_after", f.fit_rms_after},
                  {"held_out_max_error_before", f.held_out_max_before},
                  {"held_out_max_error_after", f.held_out_max_after},
                  {"brackets_held_before", f.held_before},
                  {"brackets_held_after", f.held_after}});
  return j;
}

std::string arching_calibration_summary(const ArchingCalibrationOutcome& o,
                                        const ArchingCalibration& t) {
  std::ostringstream s;
  const std::size_t held_out = held_out_count(o);
  s << "Critical outlet width, " << o.material << ", against " << t.rung << " (" << o.records.size()
    << " semi-angle(s), " << held_out << " held out; hopper.flow_factor=" << t.flow_factor
    << "):\n";
  for (std::size_t i = 0; i < o.records.size(); ++i) {
    const ArchingRecord& r = o.records[i];
    s << "  theta = " << format_number(in_degrees(r.observation.hopper.semi_angle), 4)
      << " deg, phi_w = " << format_number(in_degrees(*r.observation.hopper.wall_friction_angle), 4)
      << " deg" << (r.observation.held_out ? " (held out)" : "") << ": arches at "
      << mm(r.observation.arches_at) << ", flows at " << mm(r.observation.flows_at)
      << ", reference " << mm(r.observation.reference()) << "; B_c";
    for (std::size_t k = 0; k < o.fit.size(); ++k)
      s << (k ? ", " : " ") << o.fit[k].row->name << " " << mm(o.fit[k].width_before[i]) << " -> "
        << mm(o.fit[k].width_after[i]);
    s << '\n';
  }
  for (const auto& f : o.fit) {
    s << "  " << f.row->name << ": sigma_c x " << format_number(f.scale, 4)
      << " (every bracket holds B_c for " << range_text(f) << "); rms error "
      << percent(f.fit_rms_before) << " -> " << percent(f.fit_rms_after);
    if (held_out > 0)
      s << ", held-out max " << percent(f.held_out_max_before) << " -> "
        << percent(f.held_out_max_after);
    s << "; brackets holding B_c " << f.held_before << " -> " << f.held_after << " of "
      << o.records.size() << '\n';
  }
  return s.str();
}

}  // namespace feedflow
