#include "designer/simulate/simulation_pictures.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <set>
#include <stdexcept>
#include <string>

#include "fullsim/cel/cel_field_snapshots.hpp"
#include "fullsim/common/hdf5_file.hpp"
#include "fullsim/common/scene_outline.hpp"
#include "fullsim/dem/particle_snapshots.hpp"
#include "models/units/quantity_format.hpp"
#include "reports/render/snapshot.hpp"

namespace fs = std::filesystem;

namespace feedflow {
namespace {

struct SnapshotEntry {
  fs::path file;
  std::string group;
  double time = 0.0;
};

// Every snapshot in `files`, in time order.
std::vector<SnapshotEntry> snapshots_in(const std::vector<fs::path>& files) {
  std::vector<SnapshotEntry> all;
  for (const auto& file : files) {
    const Hdf5File f(file, Hdf5File::Mode::read);
    if (!f.exists("/snapshots")) continue;
    for (const auto& name : f.members("/snapshots")) {
      const std::string group = "/snapshots/" + name;
      all.push_back({file, group, f.double_attribute(group, "time")});
    }
  }
  std::stable_sort(all.begin(), all.end(),
                   [](const auto& a, const auto& b) { return a.time < b.time; });
  return all;
}

// The first, middle and last snapshot (fewer when there are fewer).
std::vector<std::size_t> three_times(std::size_t count) {
  std::set<std::size_t> picked;
  if (count > 0) picked = {0, (count - 1) / 2, count - 1};
  return {picked.begin(), picked.end()};
}

std::string when(const std::vector<SnapshotEntry>& all, std::size_t k) {
  return "t = " + format_quantity(all[k].time, "s", 4) + " (" + all[k].file.filename().string() +
         ", " + all[k].group.substr(all[k].group.rfind('/') + 1) + ")";
}

render::SnapshotOptions picture_options(const std::string& quantity, const std::string& unit) {
  render::SnapshotOptions o;
  o.width = 1000;
  o.height = 600;
  o.quantity = quantity;
  o.unit = unit;
  return o;
}

ReportImage picture(render::SnapshotRenderer& renderer, const render::Scene& scene,
                    const render::SnapshotOptions& options, std::string caption) {
  return {render::encode_png(renderer.render(scene, options).image), std::move(caption)};
}

// The DEM frame has z up and y through the slab (or along the drum's axis); the renderer's front
// view looks along -z with y up: (x, y, z) -> (x, z, -y), a rotation.
render::Vec3 front_view(double x, double y, double z) { return {x, z, -y}; }

void add_outline(const SceneOutline& outline, bool dem_frame, render::Scene& scene) {
  for (const auto& s : outline)
    scene.segments.push_back(
        dem_frame ? render::WallSegment{front_view(s.a.x(), s.a.y(), s.a.z()),
                                        front_view(s.b.x(), s.b.y(), s.b.z())}
                  : render::WallSegment{{s.a.x(), s.a.y(), s.a.z()}, {s.b.x(), s.b.y(), s.b.z()}});
}

// The q-quantile of `values` (0 when empty).
double quantile(std::vector<double> values, double q) {
  if (values.empty()) return 0.0;
  const auto k = static_cast<std::size_t>(q * static_cast<double>(values.size() - 1));
  std::nth_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(k), values.end());
  return values[k];
}

// The snapshots that hold particles (an emptied hopper's last ones hold none).
std::vector<SnapshotEntry> with_particles(std::vector<SnapshotEntry> all) {
  std::erase_if(all, [](const SnapshotEntry& e) {
    const Hdf5File f(e.file, Hdf5File::Mode::read);
    return f.dims(e.group + "/radius").at(0) == 0;
  });
  return all;
}

std::vector<ReportImage> particle_pictures(const std::vector<fs::path>& files) {
  const auto all = with_particles(snapshots_in(files));
  const auto picked = three_times(all.size());
  if (picked.empty()) return {};
  SceneOutline outline;
  {
    const Hdf5File f(files.front(), Hdf5File::Mode::read);
    outline = read_outline(f, "/outline");
  }
  std::vector<ParticleSnapshot> shots;
  double top_speed = 0.0;  // one colour scale for the three times
  for (std::size_t k : picked) {
    shots.push_back(read_particle_snapshot(all[k].file, all[k].group));
    std::vector<double> speed;
    for (const auto& v : shots.back().velocity) speed.push_back(v.norm());
    top_speed = std::max(top_speed, quantile(speed, 0.99));
  }
  if (!(top_speed > 0.0)) top_speed = 1e-3;

  render::SnapshotRenderer renderer;
  std::vector<ReportImage> speed_pictures, layer_pictures;
  for (std::size_t n = 0; n < shots.size(); ++n) {
    const ParticleSnapshot& s = shots[n];
    render::Scene scene;
    add_outline(outline, true, scene);
    std::set<int> layers;
    for (std::size_t i = 0; i < s.position.size(); ++i) {
      const render::Vec3 p = front_view(s.position[i].x(), s.position[i].y(), s.position[i].z());
      scene.particles.x.push_back(p.x);
      scene.particles.y.push_back(p.y);
      scene.particles.z.push_back(p.z);
      scene.particles.radius.push_back(s.radius[i]);
      scene.particles.value.push_back(s.velocity[i].norm());
      scene.particles.layer.push_back(static_cast<std::int32_t>(std::max(0.0, s.layer[i])));
      layers.insert(scene.particles.layer.back());
    }
    const std::string count = std::to_string(s.position.size()) + " particles";
    auto by_speed = picture_options("speed", "m/s");
    by_speed.value_lo = 0.0;
    by_speed.value_hi = top_speed;
    speed_pictures.push_back(
        picture(renderer, scene, by_speed,
                "DEM particles coloured by speed at " + when(all, picked[n]) + ", " + count +
                    "; colour scale 0-" + format_quantity(top_speed, "m/s", 3) +
                    " (the 99th percentile; faster grains at its top colour)."));
    if (layers.size() > 1) {  // a scene that marks no layers has nothing to show this way
      auto by_layer = picture_options("initial layer", "");
      by_layer.colouring = render::ParticleColouring::by_layer;
      layer_pictures.push_back(
          picture(renderer, scene, by_layer,
                  "DEM particles coloured by the layer they started in at " + when(all, picked[n]) +
                      ": bands that stay level mean the whole bed "
                      "moves (mass flow); bands pulled down in the middle only, funnel flow."));
    }
  }
  speed_pictures.insert(speed_pictures.end(), layer_pictures.begin(), layer_pictures.end());
  return speed_pictures;
}

render::FieldGrid field_grid(const cel::CelFieldSnapshot& s, const std::vector<double>& value) {
  render::FieldGrid g;
  g.origin_x = s.origin_x;
  g.origin_y = s.origin_y;
  g.cell_size = s.cell_size;
  g.nx = s.nx;
  g.ny = s.ny;
  g.value = value;
  g.volume_fraction = s.volume_fraction;
  return g;
}

std::vector<ReportImage> field_pictures(const fs::path& file) {
  const auto all = snapshots_in({file});
  const auto picked = three_times(all.size());
  if (picked.empty()) return {};
  std::vector<cel::CelFieldSnapshot> shots;
  double top_speed = 0.0;
  for (std::size_t k : picked) {
    shots.push_back(cel::read_cel_field_snapshot(file, all[k].group));
    const auto& v = shots.back().velocity;
    for (std::size_t c = 0; c < shots.back().volume_fraction.size(); ++c)
      if (shots.back().volume_fraction[c] >= 0.5)
        top_speed = std::max(top_speed, std::hypot(v[3 * c], v[3 * c + 1]));
  }
  if (!(top_speed > 0.0)) top_speed = 1e-3;
  const std::string surface =
      "; cells less than half full are not drawn, the line is the free surface "
      "(volume fraction 0.5).";

  render::SnapshotRenderer renderer;
  std::vector<ReportImage> out;
  auto scene_of = [&](const cel::CelFieldSnapshot& s, const std::vector<double>& value) {
    render::Scene scene;
    scene.field = field_grid(s, value);
    add_outline(s.outline, false, scene);
    return scene;
  };
  for (std::size_t n = 0; n < shots.size(); ++n) {
    const auto& s = shots[n];
    std::vector<double> speed(s.volume_fraction.size());
    for (std::size_t c = 0; c < speed.size(); ++c)
      speed[c] = std::hypot(s.velocity[3 * c], s.velocity[3 * c + 1]);
    auto o = picture_options("speed", "m/s");
    o.value_lo = 0.0;
    o.value_hi = top_speed;
    out.push_back(picture(renderer, scene_of(s, speed), o,
                          "CEL material speed at " + when(all, picked[n]) + " on " +
                              format_quantity(s.cell_size, "mm", 3) + " cells" + surface));
  }
  const auto& last = shots.back();
  std::vector<double> stress_kpa(last.pressure.size());
  for (std::size_t c = 0; c < stress_kpa.size(); ++c) stress_kpa[c] = last.pressure[c] / 1e3;
  out.push_back(picture(renderer, scene_of(last, last.density),
                        picture_options("bulk density", "kg/m^3"),
                        "CEL bulk density (stress-dependent, through the void ratio) at " +
                            when(all, picked.back()) + surface));
  out.push_back(picture(renderer, scene_of(last, stress_kpa), picture_options("mean stress", "kPa"),
                        "CEL mean stress -tr(T)/3 at " + when(all, picked.back()) + surface));
  return out;
}

}  // namespace

std::vector<ReportImage> simulation_pictures(const fs::path& run_folder) {
  std::error_code ec;
  if (fs::is_regular_file(run_folder / "particles.h5", ec)) {
    std::vector<fs::path> files = {run_folder / "particles.h5"};
    std::vector<fs::path> continued;  // particles_from_step_<N>.h5 of restarted runs
    for (const auto& e : fs::directory_iterator(run_folder, ec)) {
      const std::string name = e.path().filename().string();
      if (name.starts_with("particles_from_step_") && name.ends_with(".h5"))
        continued.push_back(e.path());
    }
    std::sort(continued.begin(), continued.end());
    files.insert(files.end(), continued.begin(), continued.end());
    return particle_pictures(files);
  }
  if (fs::is_regular_file(run_folder / "fields.h5", ec))
    return field_pictures(run_folder / "fields.h5");
  return {};
}

std::vector<ReportImage> record_pictures(const DesignRecord& record, const fs::path& results_folder,
                                         std::ostream& warnings) {
  std::vector<ReportImage> pictures;
  for (const auto& name : record.simulation_runs) {
    // Lexically: the results folder may not exist yet (a report written with its results).
    const fs::path run = (results_folder / name).lexically_normal();
    try {
      for (auto& p : simulation_pictures(run)) pictures.push_back(std::move(p));
    } catch (const std::runtime_error& e) {
      warnings << "feedflow: warning: the report has no pictures of the run in " << run.string()
               << ": " << e.what() << '\n';
    }
  }
  return pictures;
}

}  // namespace feedflow
