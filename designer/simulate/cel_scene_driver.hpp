#pragma once
// Runs a CEL scene for `feedflow simulate`: prints the plan, continues from a checkpoint when
// asked, steps through the gravity phase and the event, samples a row of the time series at a
// fixed interval, writes field snapshots (HDF5 + XDMF) and a checkpoint at the end or on Ctrl-C,
// shows progress with an ETA and ends with the performance block.
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "designer/simulate/simulation_request.hpp"
#include "fullsim/cel/cel_scene_run.hpp"

namespace feedflow {

struct CelRunSetup {
  cel::CelScene scene;
  HypoplasticModel model;
  double sample_interval = 0.01;  // [s]
  // One row of the time series (its first value is the time).
  std::function<std::vector<double>(const cel::CelSceneRun&)> sample;
  // Optional: ends the run before the simulated time is up (flow come to rest), asked after
  // every sample with the rows so far.
  std::function<bool(const cel::CelSceneRun&, const std::vector<std::vector<double>>&)> finished;
};

struct CelRunResult {
  std::unique_ptr<cel::CelSceneRun> run;
  std::vector<std::vector<double>> samples;
  double end_time = 0.0;            // event time + simulated time after it [s]
  bool finished_early = false;      // CelRunSetup::finished said so
  SimulationEnd end = SimulationEnd::completed;
  std::vector<std::filesystem::path> files;
  double cell_updates_per_second = 0.0;
  double wall_seconds = 0.0;
};

// A CEL outcome's common part: how the run ended, its files, and the samples under `columns`.
SimulationOutcome outcome_of(const CelRunResult& r, std::vector<TimeSeriesColumn> columns);

// The wall-clock throughput row every CEL record carries (cell updates per second).
void add_throughput_result(const CelRunResult& r, DesignRecord& rec);

// The scene's material from the case (bulk density, seed deck void ratio) and the cell size
// ([cel] cell_size or `default_cell_size`).
cel::SceneMaterial scene_material(const Case& c);
double cel_cell_size(const Case& c, double default_cell_size);
HypoplasticModel cel_material_model(const Case& c);
// The model label of a CEL result row: "CEL-FEM plane strain (G-B hypoplastic, <remap>)" with
// the remap chosen by [cel] remap_order, material_flux and mixed_cells (default "donor-cell
// remap").
// `scene_flux`: the scene's material flux when the case names none (the drum's is PLIC).
std::string cel_model_label(const Case& c,
                            cel::MaterialFlux scene_flux = cel::MaterialFlux::donor_cell);

CelRunResult run_cel_scene(const SimulationRequest& request, CelRunSetup setup);

}  // namespace feedflow
