#include "designer/simulate/dem_drum_adapter.hpp"

#include <cmath>
#include <numbers>

#include "designer/simulate/dem_case_settings.hpp"
#include "designer/simulate/drum_angle_interval.hpp"
#include "designer/simulate/reduced_model_beside.hpp"
#include "fullsim/dem/scene/drum_angle_watch.hpp"
#include "fullsim/dem/scene/drum_scene.hpp"
#include "models/core/errors.hpp"
#include "models/units/angle.hpp"
#include "models/units/quantity_format.hpp"
#include "reports/result_format.hpp"

namespace feedflow {
namespace {

constexpr double kDefaultRotation = 10.0;  // [s] of rotation at most (the seed's 10 s)
constexpr double kDrumSampleInterval = 0.02;  // [s]

// A slab has no turning end plates to help carry the bed: its shell takes the case's wall
// friction (the seed FEM's slab value) instead of Table 2's P-W 0.2, with which the bed slips.
double shell_friction(const Drum& drum) {
  return drum.wall_friction_angle ? std::tan(*drum.wall_friction_angle) : 0.364;
}

DrumAngleWatch angle_watch(const Drum& drum) {
  const AngleWindows w = drum_angle_windows(drum.speed);
  return DrumAngleWatch(0.5 * drum.diameter, w.spin_up, w.window, w.tolerance);
}

class DemDrumAdapter final : public SceneAdapter {
 public:
  explicit DemDrumAdapter(const SimulationRequest& request)
      : request_(request),
        drum_(std::get<Drum>(request.case_data.equipment)),
        settings_(dem_drum_settings(request.case_data, request.ranks)),
        scene_(settings_, dem_drum_spec(request.case_data, settings_)),
        watch_(angle_watch(drum_)) {}

  std::string what() const override { return "the drum"; }

  bool restore_fill(const Hdf5File& f) override {
    if (!RainFill::saved_in(f)) return false;
    scene_.restore_fill(f);
    return fill_restored_ = true;
  }
  bool save_fill(Hdf5File& f) const override { return scene_.save_fill(f); }

  Stepper* build(std::ostream& log, ProgressSink& progress) override {
    const bool fresh = fills();
    const auto& spec = scene_.spec();
    log << "drum scene plan: "
        << (spec.slab_depth ? "periodic axial slab " + format_number(*spec.slab_depth * 1e3, 3) + " mm deep (no end walls; stands for the " +
                                  format_number(drum_.length * 1e3, 3) + " mm drum)"
                            : "full 3D drum with turning end plates")
        << ", D = " << drum_.diameter * 1e3 << " mm, fill " << drum_.fill_fraction * 100 << " %, "
        << drum_.speed * 30.0 / std::numbers::pi << " rpm; analytic cylinder shell; filled by "
        << (fresh ? scene_.rain().describe() + " (the fill line)" : std::string("rain-fall (restart: the fill is skipped)"))
        << "; the shell starts after settling; ends when the angle has converged\n";
    if (fresh) {
      if (scene_.fill(log, &progress).interrupted) return nullptr;
      scene_.start_rotation(log);
    }
    return &scene_.engine();
  }

  std::vector<TimeSeriesColumn> columns() const override {
    // time: the simulation time, as the particle snapshots and the checkpoint have it.
    return {{"time", "s"},
            {"time_after_start", "s"},
            {"dynamic_angle_of_repose", "deg"},
            {"surface_fit_valid", ""},
            {"airborne_fraction", ""},
            {"over_top_fraction", ""},
            {"solid_body_fraction", ""},
            {"shell_speed_ratio", ""},
            {"kinetic_energy", "J"}};
  }

  void restore(const Hdf5File& f) override {
    scene_.set_rotation_start(f.double_attribute("/scene", "rotation_start"));
    watch_.restore(f, "/scene/angle_watch");
  }

  void plan(SceneRunOptions& run) override {
    const Case& c = request_.case_data;
    run.label = "DEM drum";
    run.origin = run.sample_origin = scene_.rotation_start();
    run.duration = request_.end_time ? *request_.end_time : dem_drum_rotation(c);
    run.sample_interval = kDrumSampleInterval;
    run.snapshot_interval = dem_snapshot_interval(c, run.duration, kDrumSampleInterval);
    run.sample = [this] {
      const DrumSample s = scene_.sample();
      watch_.add(s);
      return std::vector<double>{scene_.engine().time(),
                                 s.time,
                                 s.angle / kDegree,
                                 s.valid ? 1.0 : 0.0,
                                 s.state.airborne_fraction,
                                 s.state.over_top_fraction,
                                 s.state.solid_body_fraction,
                                 s.state.shell_speed_ratio,
                                 s.kinetic_energy};
    };
    if (!request_.end_time)  // a given --time is run to its end
      run.stop = [this](const TimeSeries&) { return watch_.converged_reason(); };
    const double rotation_start = scene_.rotation_start();
    run.save_scene = [this, rotation_start](Hdf5File& f) {
      f.set_attribute("/scene", "rotation_start", rotation_start);
      watch_.save(f, "/scene/angle_watch");
    };
    duration_ = run.duration;
  }

  void measure(const SceneRunResult& run, DesignRecord& record) override {
    const auto steady = watch_.steady();
    const std::string law = contact_law_name(scene_.engine().effective_law());
    const bool measured = steady && steady->samples > 0;
    auto& results = record.results;
    if (measured && steady->angle != 0.0) {
      results.emplace_back(
          "dynamic_angle_of_repose",
          Estimate{steady->angle / kDegree, "deg", steady->low / kDegree, steady->high / kDegree,
                   "DEM (" + law +
                       "): mid-chord line of the free surface, mean over the steady "
                       "window (" +
                       steady->interval + "; band: 2 SD of the sampled angle)",
                   Rung::L3, ""});
      add_angle_interval(results, steady->interval_half_width, Rung::L3);
    }
    DrumRegimeCall regime;
    if (measured) regime = classify_drum_bed(steady->state);
    results.emplace_back(
        "regime", Estimate{measured ? std::string(to_string(regime.regime)) : std::string("not measured"), "",
                           std::nullopt, std::nullopt,
                           measured ? "DEM: measured bed state (" + regime.reason + ")"
                                    : "DEM: the run ended within the spin-up of " + format_number(watch_.spin_up(), 3) + " s",
                           Rung::L3, ""});
    results.emplace_back("particles", Estimate{static_cast<double>(scene_.engine().global_count()), "",
                                               std::nullopt, std::nullopt, "DEM scene", Rung::L3, ""});
    if (steady)
      results.emplace_back("steady_window", Estimate{steady->to - steady->from, "s", steady->from, steady->to,
                                                     "rotation time averaged (from-to after the start)", Rung::L3, ""});
    results.emplace_back("run_wall_time", Estimate{run.wall_seconds, "s", std::nullopt, std::nullopt,
                                                   "wall time of the rotation phase", Rung::L3, ""});
    auto& notes = record.verdict.reasons;
    if (run.end == RunEnd::interrupted) notes.push_back("interrupted: the result covers the run so far");
    if (!measured)
      notes.push_back("the run ended within the spin-up (" + format_number(watch_.spin_up(), 3) + " s of rotation): no steady "
                      "angle or regime; run longer than " + format_number(watch_.spin_up() + 2 * watch_.window(), 3) + " s");
    if (run.end == RunEnd::duration && !request_.end_time)
      notes.push_back("the angle had not converged within " + format_number(duration_, 3) +
                      " s of rotation" + (steady ? " (" + steady->interval + ")" : std::string()));
    if (fills() && scene_.trimmed() == 0)
      notes.push_back("the settled packing fell short of the fill line: the bed is below the asked fill");
    if (const std::string w = scene_.engine().spring_warning(); !w.empty()) notes.push_back(w);
  }

  std::vector<std::string> reduced_model_quantities() const override {
    return {"dynamic_angle_of_repose", "regime"};
  }

  void explain(const SceneRunResult&, DesignRecord& record) override {
    const auto steady = watch_.steady();
    Chart chart{"drum_angle_vs_time", "Dynamic angle of repose against time (DEM)",
                {"time since the shell started", "s"}, {"dynamic angle of repose", "deg"}, {}, ""};
    ChartSeries line{"DEM surface fit", SeriesStyle::line, {}, {}, {}};
    for (const auto& s : watch_.samples())
      if (s.valid) {
        line.x.push_back(s.time);
        line.y.push_back(s.angle / kDegree);
      }
    chart.series.push_back(line);
    if (steady && steady->angle != 0.0)
      chart.series.push_back({"steady mean with 2 SD band", SeriesStyle::band, {steady->from, steady->to},
                              {steady->low / kDegree, steady->low / kDegree}, {steady->high / kDegree, steady->high / kDegree}});
    if (const Estimate* e = find_estimate(record.results, reduced_model_key("dynamic_angle_of_repose")); e && e->is_number() && !line.x.empty())
      chart.series.push_back({"reduced model (feedflow design)", SeriesStyle::dashed, {0.0, line.x.back()},
                              {std::get<double>(e->value), std::get<double>(e->value)}, {}});
    chart.note = "the angle is the mid-chord slope of the surface; the band is 2 SD of the snapshots in the steady window";
    record.charts.push_back(std::move(chart));

    const auto& spec = scene_.spec();
    const double r = settings_.material.particle.radius;
    auto& a = record.assumptions;
    a.push_back("DEM drum: " + format_number(static_cast<double>(scene_.engine().global_count()), 6) + " spheres of R = " +
                format_number(r * 1e3, 3) + " mm, Table 2 parameters, law " + contact_law_name(scene_.engine().effective_law()) +
                ", time step " + format_number(scene_.engine().time_step() * 1e6, 3) + " us");
    add_time_step_warning(scene_.engine(), a);
    if (spec.slab_depth) {
      a.push_back("periodic axial slab " + format_number(*spec.slab_depth * 1e3, 3) + " mm deep standing for the " +
                  format_number(drum_.length * 1e3, 3) + " mm drum (masses scale by " + format_number(drum_.length / *spec.slab_depth, 3) +
                  "): no end-wall friction, so the angle errs low (Jop et al. 2005: tan beta rises by mu_w delta/W)");
      a.push_back("slab shell friction " + format_number(shell_friction(drum_), 3) + " (the case's wall friction angle) instead of "
                  "Table 2's P-W 0.2: without the turning end plates the bed slips on a 0.2 shell "
                  "(no slip needs mu_w > (r_g/R) sin beta, about 0.24 here)");
    } else {
      a.push_back("full 3D drum with Table 2 P-W friction 0.2 on the shell and on the end plates turning with it");
    }
    a.push_back(fills()
                    ? "filling by " + scene_.rain().describe() + " (the fill line): " + scene_.fill_report().summary()
                    : std::string("filling by rain-fall, settled and trimmed to the fill line (done by the run the "
                                  "checkpoint continues)"));
    a.push_back(
        "regime from the measured bed state (particles in flight, solid-body fraction, "
        "over-the-top "
        "fraction, surface bend, angle swing, shell slip; thresholds in "
        "fullsim/common/drum_bed_regime.hpp)");
  }

 private:
  // This run fills the drum (a new run, or the rest of a fill from its checkpoint).
  bool fills() const { return request_.restart.empty() || fill_restored_; }

  const SimulationRequest& request_;
  const Drum& drum_;
  DemSettings settings_;
  DrumScene scene_;
  DrumAngleWatch watch_;
  bool fill_restored_ = false;
  double duration_ = 0.0;
};

}  // namespace

DemSettings dem_drum_settings(const Case& c, const DemRanks& ranks) {
  DemSettings s = dem_case_settings(c, ranks);
  if (c.dem.slab_depth)
    s.material.particle_wall.friction = shell_friction(std::get<Drum>(c.equipment));
  return s;
}

DrumSceneSpec dem_drum_spec(const Case& c, const DemSettings& settings) {
  const Drum& drum = std::get<Drum>(c.equipment);
  DrumSceneSpec spec;
  spec.diameter = drum.diameter;
  spec.length = drum.length;
  spec.fill_fraction = drum.fill_fraction;
  spec.speed = drum.speed;
  spec.slab_depth = c.dem.slab_depth;
  if (c.dem.random_seed) spec.seed = static_cast<unsigned>(*c.dem.random_seed);
  require_periodic_faces(c, "drum");
  if (slab_faces_of(c) == SlabFaces::periodic && !spec.slab_depth)
    throw InputError(c.file, "dem.slab_faces",
                     "periodic faces need a [dem] slab_depth (without it the drum runs its full "
                     "length between its end walls)");
  if (spec.slab_depth) require_slab_depth(c, settings, *spec.slab_depth);
  return spec;
}

double dem_drum_rotation(const Case& c) {
  return c.dem.end_time ? *c.dem.end_time : kDefaultRotation;
}

std::unique_ptr<SceneAdapter> dem_drum_adapter(const SimulationRequest& request) {
  return std::make_unique<DemDrumAdapter>(request);
}

}  // namespace feedflow
