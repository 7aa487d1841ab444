#include "designer/simulate/dem_chute_adapter.hpp"

#include <algorithm>
#include <cmath>

#include "designer/simulate/dem_case_settings.hpp"
#include "designer/simulate/dem_layer_adapter.hpp"
#include "designer/simulate/reduced_model_beside.hpp"
#include "fullsim/dem/scene/inclined_plane_scene.hpp"
#include "models/core/errors.hpp"
#include "models/units/quantity_format.hpp"
#include "reports/result_format.hpp"

namespace feedflow {
namespace {

constexpr double kDefaultRunTime = 30.0;  // [s] after the release at most (seed: 18.8 s)
constexpr double kChuteSampleInterval = 0.02;  // [s]

InclinedPlaneSpec plane_spec(const Case& c, const DemSettings& settings) {
  const Chute& chute = std::get<Chute>(c.equipment);
  InclinedPlaneSpec spec;
  spec.angle = chute.angle;
  spec.ramp_length = chute.length;
  spec.bin_length = chute.bin_length;
  spec.bin_height = chute.bin_height;
  spec.fill_height = chute.fill_height;
  spec.gate_opening = chute.gate_opening;
  if (c.dem.slab_depth) spec.slab_depth = *c.dem.slab_depth;  // else the seed's slab
  if (c.dem.random_seed) spec.seed = static_cast<unsigned>(*c.dem.random_seed);
  require_periodic_faces(c, "inclined-plane");
  require_slab_depth(c, settings, spec.slab_depth);
  return spec;
}

class DemChuteAdapter final : public SceneAdapter {
 public:
  explicit DemChuteAdapter(const SimulationRequest& request)
      : request_(request),
        chute_(std::get<Chute>(request.case_data.equipment)),
        settings_(dem_case_settings(request.case_data, request.ranks)),
        scene_(settings_, plane_spec(request.case_data, settings_)) {}

  std::string what() const override { return "the bin"; }

  bool restore_fill(const Hdf5File& f) override {
    if (!RainFill::saved_in(f)) return false;
    scene_.restore_fill(f);
    return fill_restored_ = true;
  }
  bool save_fill(Hdf5File& f) const override { return scene_.save_fill(f); }

  Stepper* build(std::ostream& log, ProgressSink& progress) override {
    const bool fresh = fills();
    log << "inclined plane scene plan: periodic slab " << scene_.spec().slab_depth * 1e3 << " mm across the ramp "
        << "(stands for the " << chute_.width * 1e3 << " mm ramp; no lateral spill), ramp frame with tilted "
        << "gravity, bin on the ramp's upper end filled by "
        << (fresh ? scene_.rain().describe() + " (the fill height, normal to the ramp)"
                  : std::string("rain-fall (restart: the fill is skipped)"))
        << ", gate plane removed on release with a plate kept above " << chute_.gate_opening * 1e3
        << " mm, saw-tooth no-slip ramp (mesh), particles leaving the ramp end removed; ends when the kinetic "
           "energy shows the flow has stopped\n";
    if (fresh) {
      if (scene_.fill(log, &progress).interrupted) return nullptr;
      scene_.open_gate(log);
      release_ = scene_.engine().time();
    }
    return &scene_.engine();
  }

  std::vector<TimeSeriesColumn> columns() const override {
    // time: the simulation time, as the particle snapshots and the checkpoint have it.
    return {{"time", "s"},     {"time_after_release", "s"}, {"kinetic_energy", "J"},
            {"particles", ""}, {"mass_off_ramp_end", "kg"}, {"front", "m"}};
  }

  // The release time itself is kept: recomputing it from the step count rounds differently
  // from the engine's summed time, and the series' time column would drift.
  void restore(const Hdf5File& f) override { release_ = f.double_attribute("/scene", "release_time"); }

  void plan(SceneRunOptions& run) override {
    const Case& c = request_.case_data;
    run.label = "DEM inclined plane";
    run.origin = run.sample_origin = release_;
    run.duration = request_.end_time ? *request_.end_time : c.dem.end_time ? *c.dem.end_time : kDefaultRunTime;
    run.sample_interval = kChuteSampleInterval;
    run.snapshot_interval = dem_snapshot_interval(c, run.duration, kChuteSampleInterval);
    run.sample = [this] {
      const DemEngine& e = scene_.engine();
      return std::vector<double>{e.time(),
                                 e.time() - release_,
                                 e.kinetic_energy(),
                                 static_cast<double>(e.global_count()),
                                 e.sunk().mass,
                                 scene_.deposit().front};
    };
    if (!request_.end_time)
      run.stop = [this](const TimeSeries&) {
        return scene_.engine().time() - release_ >= 0.2 && scene_.flow_stopped()
                   ? std::string("the flow has stopped: kinetic energy per particle below 1e-3 m g d")
                   : std::string();
      };
    const double release = release_;
    run.save_scene = [release](Hdf5File& f) { f.set_attribute("/scene", "release_time", release); };
    duration_ = run.duration;
  }

  void measure(const SceneRunResult& run, DesignRecord& record) override {
    const DepositProfile d = scene_.deposit();
    const DemEngine& e = scene_.engine();
    const double r = settings_.material.particle.radius;
    auto& results = record.results;
    results.emplace_back("deposit_thickness_mid_ramp",
                         Estimate{d.mid_ramp.value, "m", d.mid_ramp.low, d.mid_ramp.high,
                                  "DEM (" + contact_law_name(e.effective_law()) + "): highest particle top per " +
                                      format_number(2 * r * 1e3, 3) + " mm bin, mean over mid-ramp +-5 % (band: the bins' range)",
                                  Rung::L3, "mm"});
    results.emplace_back("deposit_front", Estimate{d.front, "m", std::nullopt, std::nullopt,
                                                   "DEM: farthest bin with a particle", Rung::L3, ""});
    results.emplace_back("particles_left", Estimate{static_cast<double>(e.global_count()), "", std::nullopt,
                                                    std::nullopt, "DEM scene", Rung::L3, ""});
    results.emplace_back("mass_off_ramp_end_per_width",
                         Estimate{e.sunk().mass / scene_.spec().slab_depth, "kg/m", std::nullopt,
                                  std::nullopt, "DEM: slab mass through the ramp end / slab depth", Rung::L3, ""});
    results.emplace_back("run_wall_time", Estimate{run.wall_seconds, "s", std::nullopt, std::nullopt,
                                                   "wall time of the flow phase", Rung::L3, ""});
    auto& notes = record.verdict.reasons;
    if (run.end == RunEnd::interrupted) notes.push_back("interrupted: the deposit is the state so far");
    else if (run.end == RunEnd::duration && !request_.end_time)
      notes.push_back("the flow had not stopped within " + format_number(duration_, 3) + " s: the deposit is still moving");
    if (d.front < 0.5 * chute_.length)
      notes.push_back("the deposit ends at " + format_number(d.front, 3) + " m, before mid-ramp: h_stop at mid-ramp is 0");
    if (const std::string w = e.spring_warning(); !w.empty()) notes.push_back(w);
  }

  std::vector<std::string> reduced_model_quantities() const override {
    return {"stopping_thickness", "deposit_thickness_mid_ramp"};
  }

  void explain(const SceneRunResult&, DesignRecord& record) override {
    const DepositProfile d = scene_.deposit();
    Chart profile{"deposit_profile_dem", "Deposit along the ramp once flow stops (DEM)", {"distance from the gate", "m"},
                  {"deposit height", "mm"}, {}, ""};
    ChartSeries h{"DEM: highest particle top", SeriesStyle::line, {}, {}, {}};
    for (std::size_t b = 0; b < d.x.size(); ++b) {
      h.x.push_back(d.x[b]);
      h.y.push_back(d.height[b] * 1e3);
    }
    profile.series.push_back(h);
    if (const Estimate* e = find_estimate(record.results, reduced_model_key("stopping_thickness")); e && e->is_number())
      profile.series.push_back({"h_stop (reduced model)", SeriesStyle::dashed, {0.0, chute_.length},
                                {std::get<double>(e->value) * 1e3, std::get<double>(e->value) * 1e3}, {}});
    profile.note = "as the seed's DEM measured it: the highest particle along the ramp";
    record.charts.push_back(std::move(profile));

    const DemEngine& e = scene_.engine();
    const double r = scene_.settings().material.particle.radius;
    const double slab = scene_.spec().slab_depth;
    auto& a = record.assumptions;
    a.push_back("DEM inclined plane: spheres of R = " + format_number(r * 1e3, 3) + " mm, Table 2 parameters, law " +
                contact_law_name(e.effective_law()) + ", time step " + format_number(e.time_step() * 1e6, 3) + " us");
    add_time_step_warning(e, a);
    a.push_back("periodic slab " + format_number(slab * 1e3, 3) + " mm deep standing for the " + format_number(chute_.width * 1e3, 3) +
                " mm ramp (masses scale by " + format_number(chute_.width / slab, 3) + "); no side walls or lateral spill");
    a.push_back("the bin stands on the upper end of the ramp with its walls normal to it (the seed gives no drawing)");
    a.push_back("no-slip ramp as a saw-tooth mesh (45 deg faces, period 2R, height R) standing for the glued chips; "
                "the deposit height is measured above the teeth's crests");
    a.push_back(fills()
                    ? "filling by " + scene_.rain().describe() + " (the fill height), against the closed gate: " +
                          scene_.fill_report().summary()
                    : std::string("filling by rain-fall against the closed gate, settled and trimmed to the fill "
                                  "height (done by the run the checkpoint continues)"));
  }

 private:
  // This run fills the bin (a new run, or the rest of a fill from its checkpoint).
  bool fills() const { return request_.restart.empty() || fill_restored_; }

  const SimulationRequest& request_;
  const Chute& chute_;
  DemSettings settings_;
  InclinedPlaneScene scene_;
  bool fill_restored_ = false;
  double release_ = 0.0;
  double duration_ = 0.0;
};

}  // namespace

std::unique_ptr<SceneAdapter> dem_chute_adapter(const SimulationRequest& request) {
  if (request.case_data.dem.stopping_layer) return dem_layer_adapter(request);
  return std::make_unique<DemChuteAdapter>(request);
}

}  // namespace feedflow
