#include "designer/design/hopper_snapshot.hpp"

#include <algorithm>
#include <cmath>
#include <map>

#include "models/hopper/bin_stresses.hpp"
#include "models/hopper/hopper_slice_stresses.hpp"
#include "models/units/quantity_format.hpp"
#include "reports/render/snapshot.hpp"

namespace feedflow {
namespace {

std::optional<double> number_input(const DesignRecord& r, const std::string& key) {
  for (const auto& in : r.inputs)
    if (in.key == key && std::holds_alternative<double>(in.value)) return std::get<double>(in.value);
  return std::nullopt;
}

std::optional<std::string> label_input(const DesignRecord& r, const std::string& key) {
  for (const auto& in : r.inputs)
    if (in.key == key && std::holds_alternative<std::string>(in.value)) return std::get<std::string>(in.value);
  return std::nullopt;
}

// sigma_v at height y above the apex, linear between the profile's points [Pa].
double stress_at(const std::vector<HopperStressPoint>& profile, double y) {
  auto above = std::lower_bound(profile.rbegin(), profile.rend(), y,
                                [](const HopperStressPoint& p, double h) { return p.height < h; });
  if (above == profile.rbegin()) return profile.back().vertical;
  if (above == profile.rend()) return profile.front().vertical;
  const auto below = std::prev(above);
  const double t = (y - below->height) / (above->height - below->height);
  return below->vertical + t * (above->vertical - below->vertical);
}

}  // namespace

std::optional<ReportImage> hopper_stress_snapshot(const DesignRecord& r) {
  if (r.kind != EquipmentKind::hopper) return std::nullopt;
  Hopper h;
  const auto shape = label_input(r, "hopper.shape");
  const auto theta = number_input(r, "hopper.semi_angle"), outlet = number_input(r, "hopper.outlet_width"),
             fill = number_input(r, "hopper.fill_height"), bin = number_input(r, "hopper.bin_width"),
             wall = number_input(r, "hopper.wall_friction_angle"),
             density = number_input(r, "material.bulk.density"),
             delta = number_input(r, "material.flow_properties.effective_friction_angle");
  if (!shape || !theta || !outlet || !fill || !bin || !wall || !density || !delta) return std::nullopt;
  h.shape = *shape;
  h.semi_angle = *theta;
  h.outlet_width = *outlet;
  h.fill_height = *fill;
  h.bin_width = *bin;
  h.slot_length = number_input(r, "hopper.slot_length");
  h.wall_friction_angle = *wall;
  const auto profile = emptying_silo_profile(h, *density, *delta, *wall, StressRatioRule::schulze);
  if (profile.empty()) return std::nullopt;

  // The cross-section: heights above the apex, x across; cells half-covered at the walls get
  // their covered fraction (2 x 2 samples), so the free surface and the walls read cleanly.
  const double t = std::tan(h.semi_angle), h0 = h.outlet_height(), ht = h.transition_height();
  const double half = 0.5 * h.bin_width, top = std::max(h.fill_height, ht) + 0.08 * h.bin_width;
  render::FieldGrid grid;
  grid.cell_size = h.bin_width / 150.0;
  grid.nx = 150;
  grid.ny = static_cast<int>(std::ceil((top - h0) / grid.cell_size));
  grid.origin_x = -half;
  grid.origin_y = h0;
  grid.value.assign(static_cast<std::size_t>(grid.nx) * grid.ny, 0.0);
  grid.volume_fraction.assign(grid.value.size(), 0.0);
  auto inside = [&](double x, double y) {
    if (y < h0 || y > h.fill_height) return false;
    return std::abs(x) <= std::min(half, y * t);
  };
  for (int j = 0; j < grid.ny; ++j)
    for (int i = 0; i < grid.nx; ++i) {
      const double x0 = grid.origin_x + i * grid.cell_size, y0 = grid.origin_y + j * grid.cell_size;
      int covered = 0;
      for (double fx : {0.25, 0.75})
        for (double fy : {0.25, 0.75}) covered += inside(x0 + fx * grid.cell_size, y0 + fy * grid.cell_size);
      grid.volume_fraction[grid.index(i, j)] = covered / 4.0;
      grid.value[grid.index(i, j)] = stress_at(profile, y0 + 0.5 * grid.cell_size) / 1e3;
    }
  render::Scene scene;
  scene.field = grid;
  for (double side : {-1.0, 1.0}) {
    scene.segments.push_back({{side * 0.5 * h.outlet_width, h0, 0}, {side * half, ht, 0}});
    scene.segments.push_back({{side * half, ht, 0}, {side * half, top, 0}});
  }
  render::SnapshotOptions options;
  options.width = 1000;
  options.height = 800;
  options.quantity = "mean vertical stress";
  options.unit = "kPa";
  options.value_lo = 0.0;
  const render::Snapshot shot = render::render_snapshot(scene, options);
  return ReportImage{render::encode_png(shot.image),
                     "Hopper cross-section filled to " + format_quantity(h.fill_height, "m", 3) +
                         " above the apex, coloured by the mean vertical stress while emptying (Janssen in the "
                         "bin, the passive slice below; constant bulk density). Walls at " +
                         format_quantity(h.semi_angle, "deg", 3) + ", outlet " + format_quantity(h.outlet_width, "mm", 3) +
                         "."};
}

}  // namespace feedflow
