#include "designer/simulate/cel_scene_adapter.hpp"

#include "models/core/errors.hpp"

namespace feedflow {
namespace {

// Seed deck initial void ratio (data.md 7.2: e0 = 0.7102 of the "engineered" pine).
constexpr double kSeedVoidRatio = 0.7102;
constexpr std::size_t kMaxCells = 4'000'000;

cel::RemapOptions remap_options(const Case& c, cel::MaterialFlux scene_flux) {
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

std::string model_label_of(const Case& c, const cel::RemapOptions& o, const cel::CelGrid& grid) {
  const bool second = o.second_order_stress || o.second_order_void_ratio ||
                      o.second_order_density || o.second_order_momentum;
  const bool donor_cell = o.material_flux == cel::MaterialFlux::donor_cell;
  std::string remap = second ? "second-order" : donor_cell ? "donor-cell" : "first-order";
  if (o.material_flux == cel::MaterialFlux::plic) remap += ", PLIC";
  if (o.material_flux == cel::MaterialFlux::limited) remap += ", limited volume fraction";
  if (c.cel.mixed_cells == "void_first") remap += ", void-first mixed cells";
  if (c.cel.wall_cells == "cut") remap += ", cut cells at the walls";
  return std::string("CEL-FEM ") + cel::symmetry_name(grid.symmetry) + " (G-B hypoplastic, " + remap + " remap)";
}

HypoplasticModel material_model(const Case& c) {
  if (!c.material.hypoplastic)
    throw InputError(c.file, "material",
                     "material '" + c.material.name +
                         "' has no [hypoplastic] parameters; the CEL-FEM solver needs them");
  return make_hypoplastic_model(*c.material.hypoplastic);
}

}  // namespace

cel::SceneMaterial scene_material(const Case& c) { return {c.material.bulk.density, kSeedVoidRatio}; }

double cel_cell_size(const Case& c, double default_cell_size) {
  return c.cel.cell_size.value_or(default_cell_size);
}

CelSceneAdapter::CelSceneAdapter(const SimulationRequest& request, cel::CelScene scene,
                                 double sample_interval)
    : request_(request), scene_(std::move(scene)), sample_interval_(sample_interval) {
  const Case& c = request.case_data;
  if (scene_.grid.cell_count() > kMaxCells)
    throw InputError(c.file, "cel.cell_size", "gives " + std::to_string(scene_.grid.cell_count()) +
                                                  " cells; choose a larger cell size");
  scene_.options.remap = remap_options(c, scene_.options.remap.material_flux);
  if (c.cel.mixed_cells == "void_first") scene_.options.mixed_cells = cel::MixedCellRule::void_first;
  if (c.cel.mixed_cells == "equal_strain_rate")
    scene_.options.mixed_cells = cel::MixedCellRule::equal_strain_rate;
  if (c.cel.time_step_safety) scene_.options.time_step.safety = *c.cel.time_step_safety;
  if (c.cel.wall_cells == "cut") scene_.options.wall_cells = cel::WallCells::cut;
  model_label_ = model_label_of(c, scene_.options.remap, scene_.grid);
}

Stepper* CelSceneAdapter::build(std::ostream&, ProgressSink&) {
  run_.emplace(scene_, material_model(request_.case_data));
  return &*run_;
}

void CelSceneAdapter::plan(SceneRunOptions& run) {
  const Case& c = request_.case_data;
  run.label = "CEL " + scene_.name;
  run.latest_origin = scene_.gravity.max_time;
  run.duration = request_.end_time.value_or(c.cel.end_time.value_or(scene_.event_duration));
  run.sample_origin = 0.0;
  run.sample_at_origin = false;
  run.sample_interval = sample_interval_;
  run.snapshot_interval = c.cel.snapshot_interval.value_or(0.1);
  run.sample = [this] { return sample(); };
  if (!request_.end_time)  // a given --time is run to its end
    run.stop = [this](const TimeSeries& s) { return stop(s); };
}

bool CelSceneAdapter::reached_event(DesignRecord& record) const {
  if (run_->phase() == cel::ScenePhase::event) return true;
  record.verdict.reasons.push_back("the run ended in the gravity phase: nothing measured");
  return false;
}

void CelSceneAdapter::add_throughput(DesignRecord& record) const {
  record.results.emplace_back("cell_updates_per_second",
                              Estimate{run_->cell_updates_per_second(), "1/s", std::nullopt, std::nullopt,
                                       "wall-clock throughput of the steps", Rung::L2, ""});
}

void CelSceneAdapter::add_overfilled_share(DesignRecord& record) const {
  const cel::CelSolver& s = run_->solver();
  const double grid = s.total_mass();
  record.results.emplace_back(
      "overfilled_mass_share",
      Estimate{grid > 0.0 ? 100.0 * s.overfilled_mass() / grid : 0.0, "%", std::nullopt, std::nullopt,
               "mass held above the density the cells' void ratio allows, at the end (carried along the walls' "
               "staircase), share of the mass on the grid",
               Rung::L2, ""});
}

}  // namespace feedflow
