#include "designer/simulate/cel_scene_driver.hpp"

#include <omp.h>

#include <cmath>
#include <cstdio>
#include <iostream>

#include "fullsim/cel/cel_checkpoint.hpp"
#include "fullsim/cel/cel_field_snapshots.hpp"
#include "fullsim/common/interrupt_request.hpp"
#include "fullsim/common/progress_line.hpp"
#include "fullsim/common/run_report.hpp"
#include "models/core/errors.hpp"

namespace feedflow {

namespace {
// Seed deck initial void ratio (data.md 7.2: e0 = 0.7102 of the "engineered" pine).
constexpr double kSeedVoidRatio = 0.7102;
}  // namespace

cel::SceneMaterial scene_material(const Case& c) {
  return {c.material.bulk.density, kSeedVoidRatio};
}

double cel_cell_size(const Case& c, double default_cell_size) {
  return c.cel.cell_size.value_or(default_cell_size);
}

namespace {
cel::RemapOptions cel_remap_options(const Case& c, cel::MaterialFlux scene_flux) {
  cel::RemapOptions o;
  o.material_flux = scene_flux;
  const std::string& order = c.cel.remap_order;
  o.second_order_stress = order == "second" || order == "second_stress";
  o.second_order_void_ratio = order == "second" || order == "second_void_ratio";
  o.second_order_density = order == "second" || order == "second_density";
  o.second_order_momentum = order == "second" || order == "second_momentum";
  if (c.cel.material_flux == "donor_cell") o.material_flux = cel::MaterialFlux::donor_cell;
  if (c.cel.material_flux == "limited") o.material_flux = cel::MaterialFlux::limited;
  if (c.cel.material_flux == "plic") o.material_flux = cel::MaterialFlux::plic;
  return o;
}

std::string remap_text(const cel::RemapOptions& o) {
  std::string state = "first-order";
  if (o.second_order_stress || o.second_order_void_ratio || o.second_order_density ||
      o.second_order_momentum) {
    state = "second-order (van Leer MUSCL:";
    if (o.second_order_stress) state += " stress";
    if (o.second_order_void_ratio) state += " void ratio";
    if (o.second_order_density) state += " density";
    if (o.second_order_momentum) state += " momentum";
    state += ")";
  }
  const char* flux = o.material_flux == cel::MaterialFlux::plic      ? "PLIC (Youngs)"
                     : o.material_flux == cel::MaterialFlux::limited ? "limited MUSCL"
                                                                     : "donor-cell";
  return state + " state, " + flux + " material flux";
}
}  // namespace

std::string cel_model_label(const Case& c, cel::MaterialFlux scene_flux) {
  const cel::RemapOptions o = cel_remap_options(c, scene_flux);
  const bool second = o.second_order_stress || o.second_order_void_ratio ||
                      o.second_order_density || o.second_order_momentum;
  const bool donor_cell = o.material_flux == cel::MaterialFlux::donor_cell;
  std::string remap = second ? "second-order" : donor_cell ? "donor-cell" : "first-order";
  if (o.material_flux == cel::MaterialFlux::plic) remap += ", PLIC";
  if (o.material_flux == cel::MaterialFlux::limited) remap += ", limited volume fraction";
  if (c.cel.mixed_cells == "void_first") remap += ", void-first mixed cells";
  return "CEL-FEM plane strain (G-B hypoplastic, " + remap + " remap)";
}

HypoplasticModel cel_material_model(const Case& c) {
  if (!c.material.hypoplastic)
    throw InputError(c.file, "material",
                     "material '" + c.material.name +
                         "' has no [hypoplastic] parameters; the CEL-FEM solver needs them");
  return make_hypoplastic_model(*c.material.hypoplastic);
}

CelRunResult run_cel_scene(const SimulationRequest& request, CelRunSetup setup) {
  const Case& c = request.case_data;
  CelRunResult result;
  const double duration = request.end_time.value_or(c.cel.end_time.value_or(setup.scene.event_duration));
  const double snapshot_interval = c.cel.snapshot_interval.value_or(0.1);
  std::ostream* log = request.log;
  const auto& g = setup.scene.grid;
  if (g.cell_count() > 4'000'000)
    throw InputError(c.file, "cel.cell_size", "gives " + std::to_string(g.cell_count()) +
                                                  " cells; choose a larger cell size");
  setup.scene.options.remap = cel_remap_options(c, setup.scene.options.remap.material_flux);
  if (c.cel.mixed_cells == "void_first") setup.scene.options.mixed_cells = cel::MixedCellRule::void_first;
  if (c.cel.mixed_cells == "equal_strain_rate")
    setup.scene.options.mixed_cells = cel::MixedCellRule::equal_strain_rate;
  result.run = std::make_unique<cel::CelSceneRun>(setup.scene, setup.model);
  cel::CelSceneRun& run = *result.run;
  const auto checkpoint = request.out / "checkpoint.h5";
  const bool restarted = !request.restart.empty();
  if (restarted) {
    try {
      cel::CelCheckpoint cp = cel::read_cel_checkpoint(request.restart, g);
      run.restore(cp.solver, cp.run);
      result.samples = std::move(cp.samples);
    } catch (const std::runtime_error& e) {
      throw InputError("--restart", "", e.what());
    }
  }
  if (log) {
    *log << "CEL-FEM plan (plane strain, hypoplastic G-B, remap: "
         << remap_text(setup.scene.options.remap) << "; mixed cells: "
         << (setup.scene.options.mixed_cells == cel::MixedCellRule::void_first ? "void first"
                                                                               : "equal strain rate")
         << ", "
         << omp_get_max_threads() << " OpenMP thread(s)):\n";
    for (const auto& line : setup.scene.plan) *log << "  " << line << '\n';
    const auto& gp = setup.scene.gravity;
    char text[800];
    std::snprintf(text, sizeof text,
                  "  gravity phase: smooth-step ramp over %.3g s, dynamic relaxation %.3g 1/s "
                  "(off after the phase), ends after %.3g s when the kinetic energy < %.0e x "
                  "its peak, at the latest at %.3g s; bulk viscosity %.3g/%.3g\n"
                  "  event: %s, then %.4g s simulated; samples every %.3g s, snapshots every "
                  "%.3g s; mass scaling: none\n",
                  gp.ramp_time, gp.settling_damping, std::max(gp.ramp_time, gp.min_time),
                  gp.kinetic_energy_ratio, gp.max_time,
                  setup.scene.options.forces.linear_bulk_viscosity,
                  setup.scene.options.forces.quadratic_bulk_viscosity,
                  setup.scene.event.description.c_str(), duration, setup.sample_interval,
                  snapshot_interval);
    *log << text;
    if (restarted)
      *log << "  restarted from " << request.restart.string() << " at t = " << run.solver().time()
           << " s\n";
  }
  cel::CelFieldSnapshots snapshots(request.out / "fields.h5", restarted);
  RunReport report("CEL-FEM performance");
  ProgressLine progress("CEL " + setup.scene.name, setup.scene.gravity.max_time + duration, "s",
                        std::cerr, request.progress);
  const long updates0 = run.solver().cell_updates(), steps0 = run.solver().step_count();
  const auto event_over = [&] {
    return run.phase() == cel::ScenePhase::event &&
           run.solver().time() >= run.event_time() + duration;
  };
  const auto next_snapshot = [&] {
    return (std::floor(run.solver().time() / snapshot_interval + 1e-9) + 1.0) * snapshot_interval;
  };
  double snapshot_at = next_snapshot();
  if (!restarted) snapshots.write(run.solver());
  while (!event_over()) {
    {
      auto scope = report.time("steps");
      run.step();
    }
    const double t = run.solver().time();
    while (t >= (static_cast<double>(result.samples.size()) + 1.0) * setup.sample_interval) {
      auto row = setup.sample(run);
      result.samples.push_back(std::move(row));
      if (setup.finished && setup.finished(run, result.samples)) result.finished_early = true;
    }
    if (result.finished_early) break;
    if (t >= snapshot_at) {
      auto scope = report.time("snapshots");
      snapshots.write(run.solver());
      snapshot_at = next_snapshot();
    }
    const double total = run.phase() == cel::ScenePhase::event ? run.event_time() + duration
                                                               : setup.scene.gravity.max_time + duration;
    progress.update(t * (setup.scene.gravity.max_time + duration) / total);
    if (interrupt_requested()) {
      result.end = SimulationEnd::interrupted;
      break;
    }
  }
  progress.finish();
  {
    auto scope = report.time("checkpoint");
    write_cel_checkpoint(checkpoint, run, result.samples);
  }
  result.end_time = run.phase() == cel::ScenePhase::event ? run.event_time() + duration : 0.0;
  result.files = {snapshots.file(), snapshots.sidecar(), checkpoint};
  const double steps_seconds = report.phase_seconds("steps");
  const long updates = run.solver().cell_updates() - updates0;
  result.cell_updates_per_second = steps_seconds > 0.0 ? updates / steps_seconds : 0.0;
  result.wall_seconds = report.wall_seconds();
  char text[120];
  std::snprintf(text, sizeof text, "%.3g cell updates/s (%d thread(s))",
                result.cell_updates_per_second, omp_get_max_threads());
  report.add_figure("throughput", text);
  std::snprintf(text, sizeof text, "%ld steps, last dt %.3g s, simulated %.4g s",
                run.solver().step_count() - steps0, run.solver().last_dt(), run.solver().time());
  report.add_figure("steps", text);
  std::snprintf(text, sizeof text, "%zu of %zu cells active at the end",
                run.solver().active_cells().size(), g.cell_count());
  report.add_figure("cells", text);
  if (log) *log << report.render();
  return result;
}

SimulationOutcome outcome_of(const CelRunResult& r, std::vector<TimeSeriesColumn> columns) {
  SimulationOutcome out;
  out.end = r.end;
  out.files = r.files;
  out.series = TimeSeries(std::move(columns));
  for (const auto& row : r.samples) out.series.add_row(row);
  return out;
}

void add_throughput_result(const CelRunResult& r, DesignRecord& rec) {
  rec.results.emplace_back("cell_updates_per_second",
                           Estimate{r.cell_updates_per_second, "1/s", std::nullopt, std::nullopt,
                                    "wall-clock throughput of the steps", Rung::L2, ""});
}

}  // namespace feedflow
