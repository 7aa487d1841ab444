#include "designer/verify/cel_chute_estimate.hpp"

#include <cmath>

#include "designer/bench/measured_bench.hpp"
#include "designer/simulate/cel_chute_adapter.hpp"
#include "designer/simulate/cel_scene_adapter.hpp"
#include "fullsim/common/progress_line.hpp"
#include "models/units/quantity_format.hpp"

namespace feedflow {
namespace {

constexpr std::string_view kSeedPlane = "chute_stopping_thickness_29_5";
constexpr std::string_view kLevel = "CEL cells ";  // a level's setting: "CEL cells 20mm"

// The cell size [m] of a plain CEL level ("CEL cells 20mm"); none for another setting (a
// reduced model, a remap/flux variant).
std::optional<double> level_cell(const MeasuredAnswer& a) {
  if (a.setting.rfind(kLevel, 0) != 0 || a.setting.find(',') != std::string::npos)
    return std::nullopt;
  return std::stod(a.setting.substr(kLevel.size())) * 1e-3;
}

}  // namespace

std::optional<double> chute_cell_within(double tolerance, std::string& why) {
  const MeasuredQuestion* plane = measured_bench().find(kSeedPlane);
  const std::string within = format_number(100.0 * tolerance, 3) + " %";
  if (!plane || !plane->reference) {
    why = "the shipped bench table has no reference for the seed's plane";
    return std::nullopt;
  }
  if (!reference_resolves(*plane, tolerance)) {
    why = "the shipped bench table's reference for the seed's plane has an error bar of " +
          format_number(100.0 * plane->error_bar.value_or(0.0) / std::abs(*plane->reference), 3) +
          " %, wider than the tolerance " + within + ", so no CEL level can be shown to meet it";
    return std::nullopt;
  }
  const MeasuredAnswer* best = nullptr;
  for (const MeasuredAnswer& a : plane->answers)
    if (level_cell(a) && a.status == "done" && a.at_rest && a.error && a.wall_seconds &&
        *a.error <= tolerance && (!best || *a.wall_seconds < *best->wall_seconds))
      best = &a;
  if (!best) {
    why = "no CEL level of the seed's plane in the shipped bench table is within " + within;
    return std::nullopt;
  }
  return level_cell(*best);
}

std::optional<CelRunEstimate> estimate_cel_chute_run(const Case& c, std::optional<double> cell) {
  const MeasuredQuestion* plane = measured_bench().find(kSeedPlane);
  if (!plane) return std::nullopt;
  const double h = cell.value_or(cel_cell_size(c, kCelChuteCellSize));
  const MeasuredAnswer* nearest = nullptr;
  double nearest_cell = 0.0;
  for (const MeasuredAnswer& a : plane->answers) {
    const auto level = level_cell(a);
    if (a.status != "done" || !a.wall_seconds || !level) continue;
    const double cell = *level;
    if (!nearest || std::abs(std::log(cell / h)) < std::abs(std::log(nearest_cell / h))) {
      nearest = &a;
      nearest_cell = cell;
    }
  }
  if (!nearest) return std::nullopt;
  CelRunEstimate e;
  e.seconds = *nearest->wall_seconds * std::pow(nearest_cell / h, 3.0);
  e.text = "about " + format_duration(e.seconds) + " on " + std::to_string(nearest->cores) +
           " cores, as the seed's inclined plane at 29.5 deg took on " +
           format_quantity(nearest_cell, "mm", 3) + " cells (the shipped bench table" +
           (std::abs(nearest_cell - h) > 1e-9 * h
                ? ", scaled as the cell size^-3 to " + format_quantity(h, "mm", 3)
                : std::string()) +
           ")";
  return e;
}

}  // namespace feedflow
