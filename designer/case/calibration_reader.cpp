#include "designer/case/calibration_reader.hpp"

#include <cmath>

#include "models/hopper/critical_outlet_models.hpp"
#include "models/hopper/discharge_models.hpp"
#include "models/hopper/flow_factor_models.hpp"
#include "models/units/angle.hpp"
#include "models/units/dimension.hpp"
#include "models/units/quantity_format.hpp"

namespace feedflow {
namespace {

constexpr std::string_view kKeys[] = {"against",       "rung",   "scene",   "geometry",
                                      "density_model", "commit", "date",    "discharge",
                                      "points",        "drum",   "arching", "chute"};
constexpr std::string_view kArchingKeys[] = {"against", "rung", "scene", "geometry", "flow_factor",
                                             "commit",  "date", "rows",  "points"};
constexpr std::string_view kDrumKeys[] = {"against",      "rung",          "scene",  "end_walls",
                                          "diameter",     "fill_fraction", "commit", "date",
                                          "coefficients", "figures",       "points"};
constexpr std::string_view kDrumCoefficients[] = {"layer_fraction", "friction_shift"};
constexpr std::string_view kChuteKeys[] = {"against",       "rung",   "scene", "lowest_angle",
                                           "highest_angle", "commit", "date",  "coefficients",
                                           "figures",       "points"};
constexpr std::string_view kChuteCoefficients[] = {"theta1", "theta2", "stop_length"};
constexpr std::string_view kModelKeys[] = {"coefficients", "figures"};

const toml::table& table_at(const toml::node& node, const std::string& key, const TableContext& ctx) {
  if (!node.is_table()) throw InputError(location(node, ctx.file), key, "expected a table");
  return *node.as_table();
}

std::string required_text(const toml::table& t, std::string_view key, const TableContext& ctx) {
  const toml::node* node = t.get(key);
  if (!node) missing_key(t, ctx.dotted(key), "text", ctx.file);
  return read_text(*node, ctx.dotted(key), ctx);
}

// One of two words.
std::string required_choice(const toml::table& t, std::string_view key, std::string_view a, std::string_view b,
                            const TableContext& ctx) {
  std::string text = required_text(t, key, ctx);
  if (text != a && text != b)
    throw InputError(location(*t.get(key), ctx.file), ctx.dotted(key),
                     "expected \"" + std::string(a) + "\" or \"" + std::string(b) + "\", got \"" + text + "\"");
  return text;
}

std::map<std::string, std::string> read_figures(const toml::table& t, const TableContext& ctx) {
  std::map<std::string, std::string> out;
  if (const toml::node* f = t.get("figures")) {
    TableContext fctx = ctx;
    fctx.prefix = ctx.dotted("figures");
    for (auto&& [k, node] : table_at(*f, fctx.prefix, ctx))
      out[std::string(k.str())] = read_text(node, fctx.dotted(k.str()), fctx);
  }
  return out;
}

CalibratedModel read_model(const toml::table& t, const DischargeModel& row, const TableContext& ctx) {
  for (auto&& [k, node] : t) require_known_key(node, k.str(), kModelKeys, ctx);
  CalibratedModel m;
  const toml::node* c = t.get("coefficients");
  if (!c) missing_key(t, ctx.dotted("coefficients"), "the row's fitted coefficients", ctx.file);
  const toml::table& coefficients = table_at(*c, ctx.dotted("coefficients"), ctx);
  TableContext cctx = ctx;
  cctx.prefix = ctx.dotted("coefficients");
  std::vector<std::string_view> names;
  for (const auto& k : row.coefficients) names.push_back(k.name);
  for (auto&& [k, node] : coefficients) require_known_key(node, k.str(), names, cctx);
  for (const auto& k : row.coefficients) {
    const toml::node* v = coefficients.get(k.name);
    if (!v) missing_key(coefficients, cctx.dotted(k.name), std::string(k.meaning), ctx.file);
    const auto x = v->value<double>();
    if (!x || !(*x >= k.lowest && *x <= k.highest))
      throw InputError(location(*v, ctx.file), cctx.dotted(k.name),
                       "expected a number in [" + format_number(k.lowest, 3) + ", " + format_number(k.highest, 3) +
                           "] (" + std::string(k.meaning) + ")");
    m.coefficients[std::string(k.name)] = *x;
  }
  m.figures = read_figures(t, ctx);
  return m;
}

std::size_t point_count(const toml::table& t, const TableContext& ctx) {
  const toml::node* p = t.get("points");
  if (!p) return 0;
  const auto* points = p->as_array();
  if (!points || !points->is_array_of_tables())
    throw InputError(location(*p, ctx.file), ctx.dotted("points"),
                     "expected [[" + ctx.dotted("points") + "]] tables");
  return points->size();
}

// [calibration.drum]: c_delta in (0, 1], the friction shift within +-30 deg.
DrumCalibration read_drum(const toml::table& t, const TableContext& ctx) {
  for (auto&& [k, node] : t) require_known_key(node, k.str(), kDrumKeys, ctx);
  DrumCalibration d;
  d.against = required_choice(t, "against", "cel", "dem", ctx);
  d.rung = required_text(t, "rung", ctx);
  d.scene = required_text(t, "scene", ctx);
  const toml::node* walls = t.get("end_walls");
  if (!walls || !walls->is_boolean())
    throw InputError(walls ? location(*walls, ctx.file) : ctx.file, ctx.dotted("end_walls"),
                     "expected true or false");
  d.end_walls = walls->value<bool>().value_or(false);
  if (const toml::node* diameter = t.get("diameter")) {
    d.diameter = read_quantity(*diameter, dim::length, ctx.dotted("diameter"), ctx);
    if (!(*d.diameter > 0.0))
      throw InputError(location(*diameter, ctx.file), ctx.dotted("diameter"),
                       "expected a length above 0");
  }
  if (const toml::node* fill = t.get("fill_fraction")) {
    const auto f = fill->value<double>();
    if (!f || !(*f > 0.0 && *f < 1.0))
      throw InputError(location(*fill, ctx.file), ctx.dotted("fill_fraction"),
                       "expected a number in (0, 1)");
    d.fill_fraction = *f;
  }
  d.commit = required_text(t, "commit", ctx);
  d.date = required_text(t, "date", ctx);
  const toml::node* c = t.get("coefficients");
  if (!c) missing_key(t, ctx.dotted("coefficients"), "layer_fraction and friction_shift", ctx.file);
  TableContext cctx = ctx;
  cctx.prefix = ctx.dotted("coefficients");
  const toml::table& coefficients = table_at(*c, cctx.prefix, ctx);
  for (auto&& [k, node] : coefficients) require_known_key(node, k.str(), kDrumCoefficients, cctx);
  const toml::node* fraction = coefficients.get("layer_fraction");
  if (!fraction)
    missing_key(coefficients, cctx.dotted("layer_fraction"),
                "c_delta, the layer over the half-chord", ctx.file);
  const auto x = fraction->value<double>();
  if (!x || !(*x > 0.0 && *x <= 1.0))
    throw InputError(
        location(*fraction, ctx.file), cctx.dotted("layer_fraction"),
        "expected a number in (0, 1] (c_delta, the flowing layer over the half-chord)");
  d.layer.coefficients["layer_fraction"] = *x;
  const toml::node* shift = coefficients.get("friction_shift");
  if (!shift)
    missing_key(coefficients, cctx.dotted("friction_shift"), "an angle, e.g. \"2.5 deg\"",
                ctx.file);
  const double radians = read_quantity(*shift, dim::angle, cctx.dotted("friction_shift"), cctx);
  if (!(std::abs(radians) <= 30.0 * kDegree))
    throw InputError(location(*shift, ctx.file), cctx.dotted("friction_shift"),
                     "expected an angle within +-30 deg");
  d.layer.coefficients["friction_shift"] = radians;
  d.layer.figures = read_figures(t, ctx);
  d.points = point_count(t, ctx);
  return d;
}

// [calibration.arching]: per hopper.critical_outlet row a strength scale in [0.01, 100], fitted
// with a hopper.flow_factor row.
ArchingCalibration read_arching(const toml::table& t, const TableContext& ctx) {
  for (auto&& [k, node] : t) require_known_key(node, k.str(), kArchingKeys, ctx);
  ArchingCalibration a;
  a.against = required_choice(t, "against", "cel", "dem", ctx);
  a.rung = required_text(t, "rung", ctx);
  a.scene = required_text(t, "scene", ctx);
  a.geometry = required_choice(t, "geometry", "wedge", "conical", ctx);
  a.flow_factor = required_text(t, "flow_factor", ctx);
  if (!flow_factor_models().find(a.flow_factor)) {
    std::string rows;
    for (const auto& r : flow_factor_models().rows) (rows += rows.empty() ? "" : ", ") += r.name;
    throw InputError(location(*t.get("flow_factor"), ctx.file), ctx.dotted("flow_factor"),
                     "expected a hopper.flow_factor row (" + rows + "), got \"" + a.flow_factor +
                         "\"");
  }
  a.commit = required_text(t, "commit", ctx);
  a.date = required_text(t, "date", ctx);
  const toml::node* rows = t.get("rows");
  if (!rows) missing_key(t, ctx.dotted("rows"), "a table of hopper.critical_outlet rows", ctx.file);
  TableContext rctx = ctx;
  rctx.prefix = ctx.dotted("rows");
  std::vector<std::string_view> names;
  for (const auto& r : critical_outlet_models().rows) names.push_back(r.name);
  for (auto&& [k, node] : table_at(*rows, rctx.prefix, ctx)) {
    require_known_key(node, k.str(), names, rctx);
    TableContext mctx = rctx;
    mctx.prefix = rctx.dotted(k.str());
    const toml::table& row = table_at(node, mctx.prefix, ctx);
    for (auto&& [key, value] : row) require_known_key(value, key.str(), kModelKeys, mctx);
    const toml::node* c = row.get("coefficients");
    if (!c) missing_key(row, mctx.dotted("coefficients"), "strength_scale", ctx.file);
    TableContext cctx = mctx;
    cctx.prefix = mctx.dotted("coefficients");
    const toml::table& coefficients = table_at(*c, cctx.prefix, ctx);
    constexpr std::string_view kScale[] = {"strength_scale"};
    for (auto&& [key, value] : coefficients) require_known_key(value, key.str(), kScale, cctx);
    const toml::node* scale = coefficients.get("strength_scale");
    if (!scale)
      missing_key(coefficients, cctx.dotted("strength_scale"), "the factor on sigma_c", ctx.file);
    const auto x = scale->value<double>();
    if (!x || !(*x >= 0.01 && *x <= 100.0))
      throw InputError(
          location(*scale, ctx.file), cctx.dotted("strength_scale"),
          "expected a number in [0.01, 100] (the factor on the flow function's sigma_c)");
    CalibratedModel m;
    m.coefficients["strength_scale"] = *x;
    m.figures = read_figures(row, mctx);
    a.rows[std::string(k.str())] = std::move(m);
  }
  if (a.rows.empty())
    throw InputError(location(*rows, ctx.file), ctx.dotted("rows"),
                     "expected at least one hopper.critical_outlet row");
  a.points = point_count(t, ctx);
  return a;
}

// An angle in (0, 90) deg.
double read_inclination(const toml::node& node, const std::string& key, const TableContext& ctx) {
  const double radians = read_quantity(node, dim::angle, key, ctx);
  if (!(radians > 0.0 && radians < 90.0 * kDegree))
    throw InputError(location(node, ctx.file), key, "expected an angle in (0, 90) deg");
  return radians;
}

// [calibration.chute]: theta2 in (0, 90) deg and L in (0, 10 m], with the fitted inclinations'
// range.
ChuteCalibration read_chute(const toml::table& t, const TableContext& ctx) {
  for (auto&& [k, node] : t) require_known_key(node, k.str(), kChuteKeys, ctx);
  ChuteCalibration c;
  c.against = required_choice(t, "against", "cel", "dem", ctx);
  c.rung = required_text(t, "rung", ctx);
  c.scene = required_text(t, "scene", ctx);
  for (auto [key, angle] :
       {std::pair{"lowest_angle", &c.lowest_angle}, std::pair{"highest_angle", &c.highest_angle}}) {
    const toml::node* node = t.get(key);
    if (!node) missing_key(t, ctx.dotted(key), "an angle, e.g. \"29.5 deg\"", ctx.file);
    *angle = read_inclination(*node, ctx.dotted(key), ctx);
  }
  if (c.lowest_angle > c.highest_angle)
    throw InputError(location(*t.get("highest_angle"), ctx.file), ctx.dotted("highest_angle"),
                     "expected an angle at least lowest_angle's");
  c.commit = required_text(t, "commit", ctx);
  c.date = required_text(t, "date", ctx);
  const toml::node* node = t.get("coefficients");
  if (!node) missing_key(t, ctx.dotted("coefficients"), "theta2 and stop_length", ctx.file);
  TableContext cctx = ctx;
  cctx.prefix = ctx.dotted("coefficients");
  const toml::table& coefficients = table_at(*node, cctx.prefix, ctx);
  for (auto&& [k, v] : coefficients) require_known_key(v, k.str(), kChuteCoefficients, cctx);
  const toml::node* theta2 = coefficients.get("theta2");
  if (!theta2)
    missing_key(coefficients, cctx.dotted("theta2"), "an angle, e.g. \"41 deg\"", ctx.file);
  c.law.coefficients["theta2"] = read_inclination(*theta2, cctx.dotted("theta2"), cctx);
  if (const toml::node* theta1 = coefficients.get("theta1")) {  // fitted, else the material's
    const double t1 = read_inclination(*theta1, cctx.dotted("theta1"), cctx);
    if (!(t1 < c.law.coefficients["theta2"]))
      throw InputError(location(*theta1, ctx.file), cctx.dotted("theta1"),
                       "expected an angle below theta2's");
    c.law.coefficients["theta1"] = t1;
  }
  const toml::node* length = coefficients.get("stop_length");
  if (!length)
    missing_key(coefficients, cctx.dotted("stop_length"), "a length, e.g. \"12 mm\"", ctx.file);
  const double l = read_quantity(*length, dim::length, cctx.dotted("stop_length"), cctx);
  if (!(l > 0.0 && l <= 10.0))
    throw InputError(location(*length, ctx.file), cctx.dotted("stop_length"),
                     "expected a length in (0, 10 m] (L of Pouliquen's h_stop)");
  c.law.coefficients["stop_length"] = l;
  c.law.figures = read_figures(t, ctx);
  c.points = point_count(t, ctx);
  return c;
}

}  // namespace

Calibration read_calibration(const toml::table& t, const TableContext& ctx) {
  for (auto&& [k, node] : t) require_known_key(node, k.str(), kKeys, ctx);
  Calibration c;
  if (const toml::node* d = t.get("drum")) {
    TableContext dctx = ctx;
    dctx.prefix = ctx.dotted("drum");
    c.drum = read_drum(table_at(*d, dctx.prefix, ctx), dctx);
  }
  if (const toml::node* a = t.get("arching")) {
    TableContext actx = ctx;
    actx.prefix = ctx.dotted("arching");
    c.arching = read_arching(table_at(*a, actx.prefix, ctx), actx);
  }
  if (const toml::node* h = t.get("chute")) {
    TableContext hctx = ctx;
    hctx.prefix = ctx.dotted("chute");
    c.chute = read_chute(table_at(*h, hctx.prefix, ctx), hctx);
  }
  if (t.size() == (c.drum ? 1u : 0u) + (c.arching ? 1u : 0u) + (c.chute ? 1u : 0u))
    return c;  // no discharge part
  c.against = required_choice(t, "against", "cel", "dem", ctx);
  c.rung = required_text(t, "rung", ctx);
  c.scene = required_text(t, "scene", ctx);
  c.geometry = required_choice(t, "geometry", "wedge", "conical", ctx);
  c.density_model = required_text(t, "density_model", ctx);
  c.commit = required_text(t, "commit", ctx);
  c.date = required_text(t, "date", ctx);
  if (const toml::node* d = t.get("discharge")) {
    TableContext dctx = ctx;
    dctx.prefix = ctx.dotted("discharge");
    std::vector<std::string_view> rows;
    for (const auto& r : discharge_models().rows) rows.push_back(r.name);
    for (auto&& [k, node] : table_at(*d, dctx.prefix, ctx)) {
      require_known_key(node, k.str(), rows, dctx);
      TableContext mctx = dctx;
      mctx.prefix = dctx.dotted(k.str());
      c.discharge[std::string(k.str())] =
          read_model(table_at(node, mctx.prefix, ctx), discharge_models().at(k.str()), mctx);
    }
  }
  c.points = point_count(t, ctx);
  return c;
}

}  // namespace feedflow
