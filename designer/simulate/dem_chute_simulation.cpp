#include "designer/simulate/dem_chute_simulation.hpp"

#include <algorithm>
#include <cmath>
#include <memory>
#include <sstream>

#include "designer/design/verdict_builder.hpp"
#include "designer/simulate/dem_case_settings.hpp"
#include "designer/simulate/dem_scene_run.hpp"
#include "designer/simulate/reduced_model_beside.hpp"
#include "reports/result_format.hpp"
#include "fullsim/common/hdf5_file.hpp"
#include "fullsim/dem/scene/inclined_plane_scene.hpp"
#include "models/core/errors.hpp"

namespace feedflow {

namespace {

constexpr double kDefaultSlab = 0.015;   // [m] the seed's slab, five diameters
constexpr double kDefaultRunTime = 30.0;  // [s] after the release at most (seed: 18.8 s)

std::string fmt(double v, int digits = 3) {
  std::ostringstream s;
  s.precision(digits);
  s << v;
  return s.str();
}

const std::vector<TimeSeriesColumn> kColumns = {
    {"time", "s"}, {"kinetic_energy", "J"}, {"particles", ""}, {"mass_off_ramp_end", "kg"}, {"front", "m"}};

}  // namespace

SimulationOutcome simulate_chute_with_dem(const SimulationRequest& request) {
  const Case& c = request.case_data;
  const Chute& chute = std::get<Chute>(c.equipment);
  std::ostringstream discard;
  std::ostream& log = request.log ? *request.log : discard;
  const DemSettings settings = dem_case_settings(c);
  const double r = settings.material.particle.radius;

  InclinedPlaneSpec spec;
  spec.angle = chute.angle;
  spec.ramp_length = chute.length;
  spec.bin_length = chute.bin_length;
  spec.bin_height = chute.bin_height;
  spec.fill_height = chute.fill_height;
  spec.gate_opening = chute.gate_opening;
  spec.slab_depth = c.dem.slab_depth ? *c.dem.slab_depth : kDefaultSlab;
  if (c.dem.random_seed) spec.seed = static_cast<unsigned>(*c.dem.random_seed);
  const double cutoff = 2.0 * r * (1.0 + settings.skin_fraction);
  if (spec.slab_depth < 2.0 * cutoff)
    throw InputError(c.file, "dem.slab_depth",
                     "the periodic slab must be at least two neighbour cutoffs deep (" +
                         fmt(2.0 * cutoff * 1e3) + " mm for R = " + fmt(r * 1e3) + " mm)");
  std::unique_ptr<InclinedPlaneScene> scene =
      request.restart.empty() ? std::make_unique<InclinedPlaneScene>(settings, spec) : nullptr;
  log << "inclined plane scene plan: periodic slab " << spec.slab_depth * 1e3 << " mm across the ramp "
      << "(stands for the " << chute.width * 1e3 << " mm ramp; no lateral spill), ramp frame with tilted "
      << "gravity, bin on the ramp's upper end filled by "
      << (scene ? scene->rain().describe() + " (the fill height, normal to the ramp)"
                : std::string("rain-fall (restart: the fill is skipped)"))
      << ", gate plane removed on release with a plate kept above " << chute.gate_opening * 1e3
      << " mm, saw-tooth no-slip ramp (mesh), particles leaving the ramp end removed; ends when the kinetic "
         "energy shows the flow has stopped\n";

  long origin = 0;
  TimeSeries previous;
  if (request.restart.empty()) {
    if (scene->fill(log).interrupted) return interrupted_while_filling("the bin");
    scene->open_gate(log);
    origin = scene->engine().step();
  } else {
    Hdf5File file(request.restart, Hdf5File::Mode::read);
    const auto saved = file.read<double>("/scene/plane_origin");
    previous = read_scene_series(file, kColumns);
    file.close();
    scene = std::make_unique<InclinedPlaneScene>(settings, spec, read_dem_checkpoint(request.restart));
    origin = static_cast<long>(saved.at(0));
  }
  // The release time itself is kept in the checkpoint: recomputing it from the step count
  // rounds differently from the engine's summed time, and the series' time column would drift.
  double release = scene->engine().time();
  if (!request.restart.empty()) {
    Hdf5File file(request.restart, Hdf5File::Mode::read);
    release = file.exists("/scene/plane_release")
                  ? file.read<double>("/scene/plane_release").at(0)
                  : scene->engine().time() - (scene->engine().step() - origin) * scene->engine().time_step();
  }

  DemSceneRun run;
  run.label = "DEM inclined plane";
  run.origin_step = origin;
  run.duration = request.end_time ? *request.end_time : c.dem.end_time ? *c.dem.end_time : kDefaultRunTime;
  run.sample_interval = 0.02;
  run.snapshot_interval = c.dem.snapshot_interval ? *c.dem.snapshot_interval : 0.0;
  run.columns = kColumns;
  run.previous = previous;
  InclinedPlaneScene* plane = scene.get();
  run.sample = [plane, release](const DemEngine& e) {
    const OutletSink* sink = e.outlet_sink();
    return std::vector<double>{e.time() - release, e.kinetic_energy(), static_cast<double>(e.particles().size()),
                               sink ? sink->removed_mass() : 0.0, plane->deposit().front};
  };
  if (!request.end_time)
    run.stop = [plane, release](const DemEngine& e, const TimeSeries&) {
      return e.time() - release >= 0.2 && plane->flow_stopped()
                 ? std::string("the flow has stopped: kinetic energy per particle below 1e-3 m g d")
                 : std::string();
    };
  run.save_scene = [origin, release](Hdf5File& f) {
    f.write("/scene/plane_origin", std::vector<double>{static_cast<double>(origin)}, {1}, "step (release)");
    f.write("/scene/plane_release", std::vector<double>{release}, {1}, "s");
  };
  DemSceneResult ran = run_dem_scene(scene->engine(), request, run);

  SimulationOutcome out;
  out.series = ran.series;
  out.files = ran.files;
  out.end = ran.end;
  DesignRecord& record = out.record;
  VerdictBuilder verdict;
  const DepositProfile d = scene->deposit();
  double lo = 1e300, hi = 0.0;
  for (std::size_t b = 0; b < d.x.size(); ++b)
    if (std::abs(d.x[b] - 0.5 * chute.length) <= 0.05 * chute.length) {
      lo = std::min(lo, d.height[b]);
      hi = std::max(hi, d.height[b]);
    }
  const std::string law = contact_law_name(scene->engine().effective_law());
  record.results.emplace_back(
      "deposit_thickness_mid_ramp",
      Estimate{d.mid_ramp_height, "m", std::min(lo, d.mid_ramp_height), hi,
               "DEM (" + law + "): highest particle top per " + fmt(2 * r * 1e3) +
                   " mm bin, mean over mid-ramp +-5 % (band: the bins' range)",
               Rung::L3, "mm"});
  add_reduced_model_results(c, {"stopping_thickness", "deposit_thickness_mid_ramp"}, record);
  record.results.emplace_back("deposit_front", Estimate{d.front, "m", std::nullopt, std::nullopt,
                                                        "DEM: farthest bin with a particle", Rung::L3, ""});
  const double n = static_cast<double>(scene->engine().particles().size());
  const OutletSink* sink = scene->engine().outlet_sink();
  record.results.emplace_back("particles_left", Estimate{n, "", std::nullopt, std::nullopt, "DEM scene", Rung::L3, ""});
  record.results.emplace_back("mass_off_ramp_end_per_width",
                              Estimate{(sink ? sink->removed_mass() : 0.0) / spec.slab_depth, "kg/m", std::nullopt,
                                       std::nullopt, "DEM: slab mass through the ramp end / slab depth", Rung::L3, ""});
  record.results.emplace_back("run_wall_time", Estimate{ran.wall_seconds, "s", std::nullopt, std::nullopt,
                                                        "wall time of the flow phase", Rung::L3, ""});
  if (ran.end == SimulationEnd::interrupted) verdict.note("interrupted: the deposit is the state so far");
  else if (ran.stop_reason.empty() && !request.end_time)
    verdict.note("the flow had not stopped within " + fmt(run.duration) + " s: the deposit is still moving");
  if (d.front < 0.5 * chute.length)
    verdict.note("the deposit ends at " + fmt(d.front) + " m, before mid-ramp: h_stop at mid-ramp is 0");
  record.verdict = verdict.verdict();
  if (!verdict.judged()) record.verdict.status = VerdictStatus::unknown;

  Chart profile{"deposit_profile_dem", "Deposit along the ramp once flow stops (DEM)", {"distance from the gate", "m"},
                {"deposit height", "mm"}, {}, ""};
  ChartSeries h{"DEM: highest particle top", SeriesStyle::line, {}, {}, {}};
  for (std::size_t b = 0; b < d.x.size(); ++b) {
    h.x.push_back(d.x[b]);
    h.y.push_back(d.height[b] * 1e3);
  }
  profile.series.push_back(h);
  if (const Estimate* e = find_result(record, reduced_model_key("stopping_thickness")); e && e->is_number())
    profile.series.push_back({"h_stop (reduced model)", SeriesStyle::dashed, {0.0, chute.length},
                              {std::get<double>(e->value) * 1e3, std::get<double>(e->value) * 1e3}, {}});
  profile.note = "as the seed's DEM measured it: the highest particle along the ramp";
  record.charts.push_back(std::move(profile));

  auto& a = record.assumptions;
  a.push_back("DEM inclined plane: spheres of R = " + fmt(r * 1e3) + " mm, Table 2 parameters, law " + law +
              ", time step " + fmt(scene->engine().time_step() * 1e6) + " us");
  a.push_back("periodic slab " + fmt(spec.slab_depth * 1e3) + " mm deep standing for the " + fmt(chute.width * 1e3) +
              " mm ramp (masses scale by " + fmt(chute.width / spec.slab_depth) + "); no side walls or lateral spill");
  a.push_back("the bin stands on the upper end of the ramp with its walls normal to it (the seed gives no drawing)");
  a.push_back("no-slip ramp as a saw-tooth mesh (45 deg faces, period 2R, height R) standing for the glued chips; "
              "the deposit height is measured above the teeth's crests");
  if (request.restart.empty()) {
    a.push_back("filling by " + scene->rain().describe() + " (the fill height), against the closed gate: " +
                scene->fill_report().summary());
  } else {
    a.push_back("filling by rain-fall against the closed gate, settled and trimmed to the fill height (done by "
                "the run the checkpoint continues)");
  }
  return out;
}

}  // namespace feedflow
