#include "designer/simulate/dem_layer_adapter.hpp"

#include <algorithm>
#include <stdexcept>

#include "designer/simulate/dem_case_settings.hpp"
#include "models/core/errors.hpp"
#include "models/units/quantity_format.hpp"

namespace feedflow {
namespace {

constexpr double kLayerSampleInterval = 0.02;  // [s]
constexpr double kFirstJolt = 0.1;  // [s] after the tilt before a rest counts (run_layer's)
constexpr std::size_t kAfterTiltColumn = 1, kSpeedColumn = 2;  // of columns()
}  // namespace

StoppingLayerSpec stopping_layer_spec(const Case& c, const DemSettings& settings) {
  const Chute& chute = std::get<Chute>(c.equipment);
  StoppingLayerSpec spec;
  spec.angle = chute.angle;
  spec.thickness = *c.dem.stopping_layer;
  if (c.dem.slab_depth) spec.slab_depth = *c.dem.slab_depth;  // else the seed's slab
  if (c.dem.stopping_layer_length) spec.length = *c.dem.stopping_layer_length;  // else 20 spheres
  if (c.dem.random_seed) spec.seed = static_cast<unsigned>(*c.dem.random_seed);
  require_periodic_faces(c, "stopping-layer");
  require_slab_depth(c, settings, spec.slab_depth);
  const double d = 2.0 * settings.material.particle.radius;
  if (spec.thickness < d)
    throw InputError(c.file, "dem.stopping_layer",
                     "at least one sphere diameter (" + format_quantity(d, "mm", 3) + "), not " +
                         format_quantity(spec.thickness, "mm", 3));
  return spec;
}

namespace {

class DemLayerAdapter final : public SceneAdapter {
 public:
  explicit DemLayerAdapter(const SimulationRequest& request)
      : request_(request),
        chute_(std::get<Chute>(request.case_data.equipment)),
        settings_(dem_case_settings(request.case_data, request.ranks)),
        scene_(settings_, stopping_layer_spec(request.case_data, settings_)) {}

  std::string what() const override { return "the layer"; }

  Stepper* build(std::ostream& log, ProgressSink& progress) override {
    const bool fresh = request_.restart.empty();
    const StoppingLayerSpec& s = scene_.spec();
    log << "stopping layer scene plan: a layer " << format_quantity(s.thickness, "mm", 3)
        << " thick above the crests of the saw-tooth ramp, periodic over "
        << format_quantity(scene_.length(), "mm", 3) << " down the slope and "
        << format_quantity(s.slab_depth, "mm", 3) << " across it (no front, no bin, no end), "
        << (fresh ? scene_.rain().describe() + " under gravity normal to the ramp"
                  : std::string("rain-fall (restart: the fill and launch are skipped)"))
        << "; set flowing on a " << format_quantity(s.launch_angle, "deg", 3)
        << " ramp to a Froude number of " << format_number(s.launch_froude, 2)
        << ", then tilted to " << format_quantity(s.angle, "deg", 3)
        << "; ends when the layer is at rest or " << format_quantity(duration(), "s", 3)
        << " after the tilt\n";
    if (!fresh) {
      scene_.tilt();  // the checkpoint was written after the tilt
      return &scene_.engine();
    }
    if (scene_.fill(log, &progress).interrupted) return nullptr;
    try {
      scene_.launch(log);
    } catch (const std::runtime_error& e) {
      throw NumericalFailure(e.what());
    }
    return &scene_.engine();
  }

  std::vector<TimeSeriesColumn> columns() const override {
    return {{"time", "s"},
            {"time_after_tilt", "s"},
            {"downslope_speed", "m/s"},
            {"kinetic_energy", "J"},
            {"thickness", "m"}};
  }

  void restore(const Hdf5File& f) override {
    scene_.resume(f.double_attribute("/scene", "tilt_time"),
                  f.double_attribute("/scene", "launch_speed"));
  }

  void plan(SceneRunOptions& run) override {
    run.label = "DEM stopping layer";
    run.origin = run.sample_origin = scene_.tilt_time();
    run.duration = duration();
    run.sample_interval = kLayerSampleInterval;
    run.snapshot_interval =
        dem_snapshot_interval(request_.case_data, run.duration, kLayerSampleInterval);
    run.sample = [this] {
      const DemEngine& e = scene_.engine();
      return std::vector<double>{e.time(), e.time() - scene_.tilt_time(), scene_.downslope_speed(),
                                 e.kinetic_energy(), scene_.thickness()};
    };
    if (!request_.end_time)
      run.stop = [this](const TimeSeries& series) {
        const double t = scene_.engine().time() - scene_.tilt_time();
        if (t >= kFirstJolt && scene_.at_rest())
          return std::string("the layer is at rest: kinetic energy per particle below 1e-3 m g d");
        if (scene_.runs_away()) return run_away_reason();
        if (t < kStoppingLayerRunCap) return std::string();
        const double slowing = layer_slowing_ratio(series, kAfterTiltColumn, kSpeedColumn, t);
        if (slowing >= kLayerSlowingRatio) return steady_reason(slowing, t);
        return std::string();
      };
    const double tilt = scene_.tilt_time(), launch = scene_.launch_speed();
    run.save_scene = [tilt, launch](Hdf5File& f) {
      f.set_attribute("/scene", "tilt_time", tilt);
      f.set_attribute("/scene", "launch_speed", launch);
    };
  }

  void measure(const SceneRunResult& run, DesignRecord& record) override {
    const DemEngine& e = scene_.engine();
    const bool at_rest = scene_.at_rest(), ran_away = !at_rest && scene_.runs_away();
    const double after_tilt = e.time() - scene_.tilt_time();
    const double slowing =
        layer_slowing_ratio(run.series, kAfterTiltColumn, kSpeedColumn, after_tilt);
    double peak = 0.0;
    for (const auto& row : run.series.rows()) peak = std::max(peak, row[kSpeedColumn]);
    const std::string law = contact_law_name(e.effective_law());
    auto& results = record.results;
    results.emplace_back("layer_state",
                         Estimate{at_rest ? "at rest" : "flowing", "", std::nullopt, std::nullopt,
                                  "DEM (" + law +
                                      "): at rest when the kinetic energy per particle is below "
                                      "1e-3 m g d, " +
                                      format_quantity(after_tilt, "s", 3) + " after the tilt",
                                  Rung::L3, ""});
    results.emplace_back(
        "layer_thickness",
        Estimate{scene_.thickness(), "m", std::nullopt, std::nullopt,
                 "DEM: highest particle top above the crests per " +
                     format_quantity(2.0 * settings_.material.particle.radius, "mm", 3) +
                     " bin, mean over the periodic length, at the end (trimmed to " +
                     format_quantity(scene_.spec().thickness, "mm", 3) + ")",
                 Rung::L3, "mm"});
    results.emplace_back("layer_speed",
                         Estimate{scene_.downslope_speed(), "m/s", std::nullopt, std::nullopt,
                                  "DEM: mass-weighted mean speed down the slope at the end",
                                  Rung::L3, ""});
    results.emplace_back("layer_peak_speed",
                         Estimate{std::max(peak, scene_.launch_speed()), "m/s", std::nullopt,
                                  std::nullopt,
                                  "DEM: largest mean speed down the slope sampled after the tilt "
                                  "(the launch's included)",
                                  Rung::L3, ""});
    results.emplace_back("time_after_tilt", Estimate{after_tilt, "s", std::nullopt, std::nullopt,
                                                     at_rest    ? "to rest"
                                                     : ran_away ? "to run away (flows on)"
                                                                : "run length (still moving)",
                                                     Rung::L3, ""});
    results.emplace_back("run_wall_time",
                         Estimate{run.wall_seconds, "s", std::nullopt, std::nullopt,
                                  "wall time after the tilt", Rung::L3, ""});
    auto& notes = record.verdict.reasons;
    if (run.end == RunEnd::interrupted)
      notes.push_back("interrupted: the layer's state is the state so far");
    else if (ran_away)
      notes.push_back(run_away_reason() + ": thicker than h_stop at " +
                      format_quantity(chute_.angle, "deg", 3));
    else if (!at_rest && slowing >= kLayerSlowingRatio)
      notes.push_back(steady_reason(slowing, after_tilt) + ": thicker than h_stop at " +
                      format_quantity(chute_.angle, "deg", 3));
    else if (!at_rest)
      notes.push_back("the layer still moves " + format_quantity(after_tilt, "s", 3) +
                      " after the tilt at " + format_quantity(scene_.downslope_speed(), "m/s", 3) +
                      ", still slowing (" + slowing_text(slowing) +
                      "): called flowing, thicker than h_stop at " +
                      format_quantity(chute_.angle, "deg", 3) +
                      " as far as this run shows, though it may yet come to rest");
    if (const std::string w = e.spring_warning(); !w.empty()) notes.push_back(w);
  }

  std::vector<std::string> reduced_model_quantities() const override {
    return {"stopping_thickness"};
  }

  void explain(const SceneRunResult& run, DesignRecord& record) override {
    Chart speed{"layer_speed_dem",
                "Mean speed down the slope after the tilt (DEM stopping layer)",
                {"time after the tilt", "s"},
                {"speed", "m/s"},
                {},
                ""};
    ChartSeries u{"DEM: mass-weighted mean", SeriesStyle::line, {}, {}, {}};
    for (const auto& row : run.series.rows()) {
      u.x.push_back(row[1]);
      u.y.push_back(row[2]);
    }
    speed.series.push_back(std::move(u));
    speed.note = "a layer thinner than h_stop slows to rest; a thicker one keeps flowing";
    record.charts.push_back(std::move(speed));

    const DemEngine& e = scene_.engine();
    const StoppingLayerSpec& s = scene_.spec();
    auto& a = record.assumptions;
    a.push_back("DEM stopping layer: spheres of R = " +
                format_quantity(settings_.material.particle.radius, "mm", 3) +
                ", Table 2 parameters, law " + contact_law_name(e.effective_law()) +
                ", time step " + format_quantity(e.time_step(), "us", 3));
    add_time_step_warning(e, a);
    a.push_back("periodic down the slope (" + format_quantity(scene_.length(), "mm", 3) +
                ") and across it (" + format_quantity(s.slab_depth, "mm", 3) +
                "): a layer of uniform thickness with no front and no side walls, as "
                "Pouliquen's h_stop(angle) is defined (Silbert et al. 2001 in DEM)");
    a.push_back(
        "no-slip ramp as a saw-tooth mesh (45 deg faces, period 2R, height R) standing for "
        "the glued chips; the thickness is measured above the teeth's crests");
    a.push_back("launched on a " + format_quantity(s.launch_angle, "deg", 3) +
                " ramp before the tilt: a layer at rest tilted to the angle would measure "
                "h_start, which lies above h_stop (Pouliquen's hysteresis)");
    a.push_back(request_.restart.empty()
                    ? "filling by " + scene_.rain().describe() + ": " +
                          scene_.fill_report().summary()
                    : std::string("filled, launched and tilted by the run the checkpoint "
                                  "continues"));
  }

 private:
  double duration() const {
    const Case& c = request_.case_data;
    return request_.end_time ? *request_.end_time
           : c.dem.end_time  ? *c.dem.end_time
                             : kStoppingLayerRunLimit;
  }

  static std::string slowing_text(double ratio) {
    return "its mean speed down the slope over the last " +
           format_quantity(kLayerSlowingWindow, "s", 2) + " is " + format_number(ratio, 2) +
           " of that " + format_quantity(kLayerSlowingLag, "s", 2) + " earlier";
  }

  static std::string steady_reason(double ratio, double t) {
    return "the layer flows on steadily " + format_quantity(t, "s", 3) +
           " after the tilt: " + slowing_text(ratio);
  }

  std::string run_away_reason() const {
    return "the layer runs away: its mean speed down the slope reached " +
           format_quantity(scene_.downslope_speed(), "m/s", 3) + ", " +
           format_number(StoppingLayerScene::kRunAwaySpeedRatio, 2) + " times its launch speed (" +
           format_quantity(scene_.launch_speed(), "m/s", 3) + "), " +
           format_quantity(scene_.engine().time() - scene_.tilt_time(), "s", 3) + " after the tilt";
  }

  const SimulationRequest& request_;
  const Chute& chute_;
  DemSettings settings_;
  StoppingLayerScene scene_;
};

}  // namespace

std::unique_ptr<SceneAdapter> dem_layer_adapter(const SimulationRequest& request) {
  return std::make_unique<DemLayerAdapter>(request);
}

}  // namespace feedflow
