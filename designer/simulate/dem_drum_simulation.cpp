#include "designer/simulate/dem_drum_simulation.hpp"

#include <cmath>
#include <memory>
#include <numbers>
#include <sstream>

#include "designer/design/verdict_builder.hpp"
#include "designer/simulate/dem_case_settings.hpp"
#include "designer/simulate/dem_scene_run.hpp"
#include "designer/simulate/reduced_model_beside.hpp"
#include "reports/result_format.hpp"
#include "fullsim/common/hdf5_file.hpp"
#include "fullsim/dem/scene/drum_angle_watch.hpp"
#include "fullsim/dem/scene/drum_scene.hpp"
#include "models/core/errors.hpp"

namespace feedflow {

namespace {

constexpr double kDeg = std::numbers::pi / 180.0;
constexpr double kDefaultRotation = 10.0;  // [s] of rotation at most (the seed's 10 s)

std::string fmt(double v, int digits = 3) {
  std::ostringstream s;
  s.precision(digits);
  s << v;
  return s.str();
}

const std::vector<TimeSeriesColumn> kColumns = {
    {"time", "s"},                {"dynamic_angle_of_repose", "deg"}, {"surface_fit_valid", ""},
    {"airborne_fraction", ""},    {"over_top_fraction", ""},          {"solid_body_fraction", ""},
    {"shell_speed_ratio", ""},    {"kinetic_energy", "J"}};

}  // namespace

SimulationOutcome simulate_drum_with_dem(const SimulationRequest& request) {
  const Case& c = request.case_data;
  const Drum& drum = std::get<Drum>(c.equipment);
  std::ostringstream discard;
  std::ostream& log = request.log ? *request.log : discard;
  DemSettings settings = dem_case_settings(c);
  const double r = settings.material.particle.radius;

  DrumSceneSpec spec;
  spec.diameter = drum.diameter;
  spec.length = drum.length;
  spec.fill_fraction = drum.fill_fraction;
  spec.speed = drum.speed;
  spec.slab_depth = c.dem.slab_depth;
  if (c.dem.random_seed) spec.seed = static_cast<unsigned>(*c.dem.random_seed);
  const double cutoff = 2.0 * r * (1.0 + settings.skin_fraction);
  if (spec.slab_depth && *spec.slab_depth < 2.0 * cutoff)
    throw InputError(c.file, "dem.slab_depth",
                     "the periodic slab must be at least two neighbour cutoffs deep (" +
                         fmt(2.0 * cutoff * 1e3) + " mm for R = " + fmt(r * 1e3) + " mm)");
  // A slab has no turning end plates to help carry the bed: its shell takes the case's wall
  // friction (the seed FEM's slab value) instead of Table 2's P-W 0.2, with which the bed slips.
  const double shell_friction = drum.wall_friction_angle ? std::tan(*drum.wall_friction_angle) : 0.364;
  if (spec.slab_depth) settings.material.particle_wall.friction = shell_friction;

  std::unique_ptr<DrumScene> scene = request.restart.empty() ? std::make_unique<DrumScene>(settings, spec) : nullptr;
  log << "drum scene plan: " << (spec.slab_depth ? "periodic axial slab " + fmt(*spec.slab_depth * 1e3) +
                                                       " mm deep (no end walls; stands for the " +
                                                       fmt(drum.length * 1e3) + " mm drum)"
                                                 : "full 3D drum with turning end plates")
      << ", D = " << drum.diameter * 1e3 << " mm, fill " << drum.fill_fraction * 100 << " %, "
      << drum.speed * 30.0 / std::numbers::pi << " rpm; analytic cylinder shell; filled by "
      << (scene ? scene->rain().describe() + " (the fill line)" : std::string("rain-fall (restart: the fill is skipped)"))
      << "; the shell starts after settling; ends when the angle has converged\n";

  long origin = 0;
  TimeSeries previous;
  if (request.restart.empty()) {
    if (scene->fill(log).interrupted) return interrupted_while_filling("the drum");
    scene->start_rotation(log);
    origin = scene->engine().step();
  } else {
    Hdf5File file(request.restart, Hdf5File::Mode::read);
    const auto saved = file.read<double>("/scene/drum_origin");
    previous = read_scene_series(file, kColumns);
    file.close();
    scene = std::make_unique<DrumScene>(settings, spec, read_dem_checkpoint(request.restart));
    origin = static_cast<long>(saved.at(0));
    scene->set_rotation_start(saved.at(1));
  }
  const double period = drum.speed > 0.0 ? 2.0 * std::numbers::pi / drum.speed : 1e9;
  auto watch = std::make_shared<DrumAngleWatch>(0.5 * drum.diameter, std::max(0.5, 0.15 * period),
                                                std::max(0.5, 0.1 * period), 1.0 * kDeg);
  for (const auto& row : previous.rows()) {  // a restarted run's samples (without the profile)
    DrumSample s;
    s.time = row[0];
    s.angle = row[1] * kDeg;
    s.valid = row[2] > 0.5;
    s.state = {0.0, 0.0, row[3], row[4], row[5], row[6]};
    watch->add(s);
  }

  DemSceneRun run;
  run.label = "DEM drum";
  run.origin_step = origin;
  run.duration = request.end_time ? *request.end_time : c.dem.end_time ? *c.dem.end_time : kDefaultRotation;
  run.sample_interval = 0.02;
  run.snapshot_interval = c.dem.snapshot_interval ? *c.dem.snapshot_interval : 0.0;
  run.columns = kColumns;
  run.previous = previous;
  DrumScene* drum_scene = scene.get();
  run.sample = [drum_scene, watch](const DemEngine&) {
    const DrumSample s = drum_scene->sample();
    watch->add(s);
    return std::vector<double>{s.time, s.angle / kDeg, s.valid ? 1.0 : 0.0, s.state.airborne_fraction,
                               s.state.over_top_fraction, s.state.solid_body_fraction,
                               s.state.shell_speed_ratio, s.kinetic_energy};
  };
  if (!request.end_time)  // a given --time is run to its end
    run.stop = [watch](const DemEngine&, const TimeSeries&) {
      return watch->converged() ? std::string("converged: the mean angle of the last two windows differs by "
                                              "less than 1 deg")
                                : std::string();
    };
  const double rotation_start = scene->rotation_start();
  run.save_scene = [origin, rotation_start](Hdf5File& f) {
    f.write("/scene/drum_origin", std::vector<double>{static_cast<double>(origin), rotation_start}, {2},
            "step, s (rotation start)");
  };
  DemSceneResult ran = run_dem_scene(scene->engine(), request, run);

  SimulationOutcome out;
  out.series = ran.series;
  out.files = ran.files;
  out.end = ran.end;
  DesignRecord& record = out.record;
  VerdictBuilder verdict;
  const auto steady = watch->steady();
  const std::string dem_model = std::string("DEM (") + contact_law_name(scene->engine().effective_law()) +
                                "): mid-chord line of the free surface, mean over the steady window";
  const double n = static_cast<double>(scene->engine().particles().size());
  const bool measured = steady && steady->samples > 0;
  if (measured && steady->angle != 0.0) {
    record.results.emplace_back("dynamic_angle_of_repose",
                                Estimate{steady->angle / kDeg, "deg", steady->low / kDeg, steady->high / kDeg,
                                         dem_model + " (band: 2 SD of the sampled angle)", Rung::L3, ""});
  }
  DrumRegimeCall regime;
  if (measured) regime = classify_drum_bed(steady->state);
  record.results.emplace_back(
      "regime", Estimate{measured ? std::string(to_string(regime.regime)) : std::string("not measured"), "",
                         std::nullopt, std::nullopt,
                         measured ? "DEM: measured bed state (" + regime.reason + ")"
                                  : "DEM: the run ended within the spin-up of " + fmt(watch->spin_up()) + " s",
                         Rung::L3, ""});
  // The reduced-model values of the same quantities (feedflow design).
  add_reduced_model_results(c, {"dynamic_angle_of_repose", "regime"}, record);
  record.results.emplace_back("particles", Estimate{n, "", std::nullopt, std::nullopt, "DEM scene", Rung::L3, ""});
  if (steady)
    record.results.emplace_back("steady_window", Estimate{steady->to - steady->from, "s", steady->from, steady->to,
                                                          "rotation time averaged (from-to after the start)",
                                                          Rung::L3, ""});
  record.results.emplace_back("run_wall_time", Estimate{ran.wall_seconds, "s", std::nullopt, std::nullopt,
                                                        "wall time of the rotation phase", Rung::L3, ""});

  const std::string& required = c.design.required_regime;
  if (ran.end == SimulationEnd::interrupted) verdict.note("interrupted: the result covers the run so far");
  if (!measured)
    verdict.note("the run ended within the spin-up (" + fmt(watch->spin_up()) + " s of rotation): no steady "
                 "angle or regime; run longer than " + fmt(watch->spin_up() + 2 * watch->window()) + " s");
  else if (!required.empty()) {
    if (required == to_string(regime.regime))
      verdict.pass("the DEM bed is " + required + " as required (" + regime.reason + ")");
    else
      verdict.fail("the DEM bed is " + std::string(to_string(regime.regime)) + ", " + required +
                   " is required (" + regime.reason + ")");
  }
  if (ran.stop_reason.empty() && !request.end_time)
    verdict.note("the angle had not converged within " + fmt(run.duration) + " s of rotation");
  if (request.restart.empty() && scene->trimmed() == 0)
    verdict.note("the settled packing fell short of the fill line: the bed is below the asked fill");
  record.verdict = verdict.verdict();
  if (!verdict.judged()) record.verdict.status = VerdictStatus::unknown;

  Chart chart{"drum_angle_vs_time", "Dynamic angle of repose against time (DEM)", {"time since the shell started", "s"},
              {"dynamic angle of repose", "deg"}, {}, ""};
  ChartSeries line{"DEM surface fit", SeriesStyle::line, {}, {}, {}};
  for (const auto& s : watch->samples())
    if (s.valid) {
      line.x.push_back(s.time);
      line.y.push_back(s.angle / kDeg);
    }
  chart.series.push_back(line);
  if (steady && steady->angle != 0.0)
    chart.series.push_back({"steady mean with 2 SD band", SeriesStyle::band, {steady->from, steady->to},
                            {steady->low / kDeg, steady->low / kDeg}, {steady->high / kDeg, steady->high / kDeg}});
  if (const Estimate* e = find_result(record, reduced_model_key("dynamic_angle_of_repose")); e && e->is_number() && !line.x.empty())
    chart.series.push_back({"reduced model (feedflow design)", SeriesStyle::dashed, {0.0, line.x.back()},
                            {std::get<double>(e->value), std::get<double>(e->value)}, {}});
  chart.note = "the angle is the mid-chord slope of the surface; the band is 2 SD of the snapshots in the steady window";
  record.charts.push_back(std::move(chart));

  auto& a = record.assumptions;
  a.push_back("DEM drum: " + fmt(n, 6) + " spheres of R = " + fmt(r * 1e3) + " mm, Table 2 parameters, law " +
              contact_law_name(scene->engine().effective_law()) + ", time step " +
              fmt(scene->engine().time_step() * 1e6) + " us");
  if (spec.slab_depth)
    a.push_back("periodic axial slab " + fmt(*spec.slab_depth * 1e3) + " mm deep standing for the " +
                fmt(drum.length * 1e3) + " mm drum (masses scale by " + fmt(drum.length / *spec.slab_depth) +
                "): no end-wall friction, so the angle errs low (Jop et al. 2005: tan beta rises by mu_w delta/W)");
  if (spec.slab_depth)
    a.push_back("slab shell friction " + fmt(shell_friction) + " (the case's wall friction angle) instead of "
                "Table 2's P-W 0.2: without the turning end plates the bed slips on a 0.2 shell "
                "(no slip needs mu_w > (r_g/R) sin beta, about 0.24 here)");
  else
    a.push_back("full 3D drum with Table 2 P-W friction 0.2 on the shell and on the end plates turning with it");
  if (request.restart.empty()) {
    a.push_back("filling by " + scene->rain().describe() + " (the fill line): " +
                scene->fill_report().summary());
  } else {
    a.push_back("filling by rain-fall, settled and trimmed to the fill line (done by the run the checkpoint "
                "continues)");
  }
  a.push_back("regime from the measured bed state (particles in flight, solid-body fraction, over-the-top "
              "fraction, surface bend, angle swing, shell slip; thresholds in fullsim/dem/scene/drum_bed_regime.hpp)");
  return out;
}

}  // namespace feedflow
