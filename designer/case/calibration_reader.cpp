#include "designer/case/calibration_reader.hpp"

#include "models/hopper/discharge_models.hpp"
#include "models/units/quantity_format.hpp"

namespace feedflow {
namespace {

constexpr std::string_view kKeys[] = {"against", "rung",   "scene", "geometry", "density_model",
                                      "commit",  "date",   "discharge", "points"};
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
  if (const toml::node* f = t.get("figures")) {
    TableContext fctx = ctx;
    fctx.prefix = ctx.dotted("figures");
    for (auto&& [k, node] : table_at(*f, fctx.prefix, ctx))
      m.figures[std::string(k.str())] = read_text(node, fctx.dotted(k.str()), fctx);
  }
  return m;
}

}  // namespace

Calibration read_calibration(const toml::table& t, const TableContext& ctx) {
  for (auto&& [k, node] : t) require_known_key(node, k.str(), kKeys, ctx);
  Calibration c;
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
  if (const toml::node* p = t.get("points")) {
    const auto* points = p->as_array();
    if (!points || !points->is_array_of_tables())
      throw InputError(location(*p, ctx.file), ctx.dotted("points"), "expected [[" + ctx.dotted("points") + "]] tables");
    c.points = points->size();
  }
  return c;
}

}  // namespace feedflow
