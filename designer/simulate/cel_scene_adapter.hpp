#pragma once
// What the three CEL scenes share on their way through `feedflow simulate`: the case's [cel]
// settings applied to the scene (cell size, remap order and flux, mixed cells), the material's
// hypoplastic law, the CelSceneRun as the stepper (its gravity phase is the scene's
// preparation, its event the origin), time-series rows from t = 0 at the scene's interval,
// field snapshots every [cel] snapshot_interval (0.1 s), and the throughput row. A scene adds
// its sample, its optional stop predicate (asked unless --time is given) and its measurement.
#include <optional>
#include <string>

#include "designer/simulate/scene_adapter.hpp"
#include "fullsim/cel/cel_scene_run.hpp"

namespace feedflow {

class CelSceneAdapter : public SceneAdapter {
 public:
  std::string what() const override { return "the scene"; }
  Stepper* build(std::ostream& log, ProgressSink& progress) override;
  void plan(SceneRunOptions& run) override;

 protected:
  // `scene`: as its builder made it; the case's [cel] remap and mixed-cell rule are applied here
  // (a scene's own material flux stays unless the case names another: the drum's is PLIC).
  CelSceneAdapter(const SimulationRequest& request, cel::CelScene scene, double sample_interval);

  // One row of the time series (its first value is the time).
  virtual std::vector<double> sample() = 0;
  // A non-empty reason ends the run before its time is up (the flow has come to rest), unless
  // --time was given.
  virtual std::string stop(const TimeSeries&) const { return {}; }

  const cel::CelSceneRun& run() const { return *run_; }
  // The run reached its event (the outlet opened, the gate lifted, the shell started); when
  // not, the adapter says so in the notes and measures nothing.
  bool reached_event(DesignRecord& record) const;
  // "CEL-FEM plane strain (G-B hypoplastic, <remap> remap)".
  const std::string& model_label() const { return model_label_; }
  void add_throughput(DesignRecord& record) const;
  // The share of the grid's mass held above the density its void ratio allows, at the end
  // (carried along the walls' staircase; CelSolver::overfilled_mass).
  void add_overfilled_share(DesignRecord& record) const;

  const SimulationRequest& request_;

 private:
  cel::CelScene scene_;
  double sample_interval_;
  std::string model_label_;
  std::optional<cel::CelSceneRun> run_;
};

// The scene's material from the case (bulk density, seed deck void ratio) and the cell size
// ([cel] cell_size or `default_cell_size`).
cel::SceneMaterial scene_material(const Case& c);
double cel_cell_size(const Case& c, double default_cell_size);

}  // namespace feedflow
