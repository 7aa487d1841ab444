#include "designer/simulate/dem_hopper_simulation.hpp"

#include <cmath>
#include <cstdio>
#include <map>
#include <sstream>

#include "reports/result_format.hpp"
#include "designer/design/verdict_builder.hpp"
#include "designer/simulate/dem_hopper_scene.hpp"
#include "designer/simulate/dem_scene_run.hpp"
#include "designer/simulate/reduced_model_beside.hpp"
#include "fullsim/dem/scene/discharge_measurement.hpp"
#include "fullsim/dem/scene/flow_order.hpp"
#include "models/core/errors.hpp"

namespace feedflow {
namespace {

constexpr double kSampleInterval = 0.01;  // [s] time-series rows
constexpr double kConvergedHalfWidth = 0.05;  // the rate's interval within +-5 % ends the run
constexpr std::size_t kConvergedBatches = 10;

std::string format(const char* fmt, auto... args) {
  char buf[500];
  std::snprintf(buf, sizeof buf, fmt, args...);
  return buf;
}

std::vector<TimeSeriesColumn> hopper_columns() {
  return {{"time", "s"},
          {"time_after_opening", "s"},
          {"discharged_mass", "kg"},
          {"particles_in_domain", ""},
          {"mass_in_domain", "kg"},
          {"kinetic_energy", "J"}};
}

std::vector<double> column(const TimeSeries& s, std::size_t c) {
  std::vector<double> v;
  for (const auto& r : s.rows()) v.push_back(r[c]);
  return v;
}

SteadyRateSettings rate_settings() {
  SteadyRateSettings r;
  r.batch_duration = 0.05;
  r.min_batches = 5;
  return r;
}

DischargeState state_of(const DemEngine& e, double opening_time, const ArchCriterion& arch) {
  const OutletSink* sink = e.outlet_sink();
  double last = opening_time;
  if (sink && !sink->events().empty()) last = std::max(last, sink->events().back().time);
  return discharge_state(e.time(), last, e.kinetic_energy(), e.particles().total_mass(),
                         e.particles().size(), arch);
}

Estimate number(double v, const std::string& unit, std::optional<double> lo,
                std::optional<double> hi, const std::string& model,
                const std::string& display = "") {
  return Estimate{v, unit, lo, hi, model, Rung::L3, display};
}
Estimate label(const std::string& text, const std::string& model) {
  return Estimate{text, "", std::nullopt, std::nullopt, model, Rung::L3, ""};
}

}  // namespace

SimulationOutcome simulate_hopper_with_dem(const SimulationRequest& request) {
  const Case& c = request.case_data;
  std::ostringstream discard;
  std::ostream& log = request.log ? *request.log : discard;
  DemHopperScene scene = hopper_scene_from_case(c);
  std::optional<DemEngine> prepared = prepare_hopper_scene(scene, request, log);
  if (!prepared) return interrupted_while_filling("the hopper");
  SimulationOutcome outcome;
  DemEngine& engine = *prepared;
  const ArchCriterion arch;

  DemSceneRun run;
  run.label = "DEM hopper";
  run.origin_step = scene.opening_step;
  run.duration = request.end_time.value_or(scene.default_duration);
  run.sample_interval = kSampleInterval;
  run.snapshot_interval = scene.snapshot_interval;
  run.columns = hopper_columns();
  if (!request.restart.empty()) {
    const Hdf5File f(request.restart, Hdf5File::Mode::read);
    run.previous = read_scene_series(f, run.columns);
  }
  const double t_open = scene.opening_time;
  run.sample = [t_open](const DemEngine& e) {
    const OutletSink* sink = e.outlet_sink();
    double out = 0.0;
    if (sink)
      for (const auto& ev : sink->events())
        if (ev.time > t_open) out += ev.mass;
    return std::vector<double>{e.time(), e.time() - t_open, out,
                               static_cast<double>(e.particles().size()),
                               e.particles().total_mass(), e.kinetic_energy()};
  };
  run.stop = [t_open, arch](const DemEngine& e, const TimeSeries& s) -> std::string {
    const DischargeState state = state_of(e, t_open, arch);
    if (state == DischargeState::arched)
      return format("arched: nothing out for %.3g s and the kinetic energy below that of the "
                    "fill moving at %.3g m/s", arch.quiet_time, arch.speed);
    if (state == DischargeState::emptied) return "the hopper has emptied";
    const SteadyRate r = steady_discharge_rate(column(s, 1), column(s, 2), 0.0, rate_settings());
    if (r.found && r.batches >= kConvergedBatches &&
        r.high - r.low < 2.0 * kConvergedHalfWidth * r.rate)
      return "converged: the steady rate's 95 % interval is within +-5 %";
    return "";
  };
  run.save_scene = [&scene](Hdf5File& f) { save_hopper_scene(scene, f); };
  DemSceneResult result = run_dem_scene(engine, request, run);
  outcome.series = result.series;
  outcome.files = result.files;
  outcome.end = result.end;

  // Measurements.
  const double scale = scene.depth_scale();
  const SteadyRate rate =
      steady_discharge_rate(column(result.series, 1), column(result.series, 2), 0.0, rate_settings());
  const DischargeState state = state_of(engine, t_open, arch);
  std::map<std::uint32_t, int> band_of;
  for (std::size_t k = 0; k < scene.initial_ids.size(); ++k)
    band_of[scene.initial_ids[k]] = static_cast<int>(scene.initial_layers[k]);
  std::vector<int> out_bands, left_bands;
  const OutletSink* sink = engine.outlet_sink();
  for (const auto& ev : sink->events())
    if (ev.time > t_open && band_of.count(ev.id)) out_bands.push_back(band_of[ev.id]);
  for (std::uint32_t id : engine.particles().id)
    if (band_of.count(id)) left_bands.push_back(band_of[id]);
  const FlowOrder order = flow_order(out_bands, left_bands);
  const double in_domain = engine.particles().total_mass();
  const double booked = in_domain + sink->removed_mass() + scene.fill.trimmed_mass;
  log << format("mass book: inserted %.9g kg = in the domain %.9g kg + through the sink %.9g kg + "
                "trimmed %.9g kg (difference %.3g kg)\n",
                scene.fill.inserted_mass, in_domain, sink->removed_mass(), scene.fill.trimmed_mass,
                booked - scene.fill.inserted_mass);

  DesignRecord& record = outcome.record;
  const std::string slab_model = format(
      "DEM slab %.3g mm deep (rung L3), scaled x %.4g (slot length %.4g m / slab depth)",
      scene.slab.depth * 1e3, scale, scene.slot_length);
  const bool arched = state == DischargeState::arched;
  const double discharged = sink->removed_mass() - scene.fill.sunk_mass;
  if (arched) {
    // An arch ends the flow: no steady rate, whatever dribbled out before it.
    const double last = sink->events().empty() ? t_open : sink->events().back().time;
    record.results.emplace_back(
        "mass_flow_rate",
        number(0.0, "kg/s", 0.0, 0.0,
               slab_model + format("; arched: %.4g kg (scaled) left before the last exit at "
                                   "%.3g s after the opening",
                                   discharged * scale, std::max(0.0, last - t_open))));
  } else if (rate.found) {
    record.results.emplace_back(
        "mass_flow_rate", number(rate.rate * scale, "kg/s", rate.low * scale, rate.high * scale,
                                 slab_model + "; steady window " + rate.describe()));
    record.results.emplace_back("mass_flow_rate_slab",
                                number(rate.rate, "kg/s", rate.low, rate.high,
                                       "DEM slab as simulated (before the depth scaling)"));
  }
  record.results.emplace_back(
      "arching", label(arched ? "arched" : state == DischargeState::emptied ? "emptied (no arch)" : "flowing",
                       format("DEM: arched when nothing leaves for %.3g s and KE < 1/2 M (%.3g m/s)^2",
                              arch.quiet_time, arch.speed)));
  record.results.emplace_back(
      "flow_pattern",
      label(order.label(), format("DEM layer bands: first-in-first-out index F = %.3f (mass flow when "
                                  "F >= %.2f), %zu bands",
                                  order.fifo_index, kMassFlowFifoIndex, static_cast<std::size_t>(scene.bands))));
  record.results.emplace_back("fifo_index", Estimate{order.fifo_index, "", std::nullopt, std::nullopt,
                                                     "pairs from different bands leaving in band order", Rung::L3, ""});
  record.results.emplace_back("discharged_mass",
                              number(discharged * scale, "kg",
                                     std::nullopt, std::nullopt, slab_model));
  record.results.emplace_back("simulated_time_after_opening",
                              number(engine.time() - t_open, "s", std::nullopt, std::nullopt,
                                     result.stop_reason.empty() ? "the run's duration" : result.stop_reason));

  // The reduced models beside it.
  add_reduced_model_results(c, {"mass_flow_rate", "critical_outlet_width", "flow_pattern"}, record);

  VerdictBuilder verdict;
  if (arched) verdict.fail("the DEM slab arches over the outlet");
  else if (rate.found && c.design.required_throughput)
    verdict.judge_at_least(rate.rate * scale, rate.low * scale, *c.design.required_throughput);
  else if (rate.found) verdict.pass("the DEM slab discharges steadily: " + rate.describe() + " (slab)");
  else verdict.note("no steady discharge window yet: run longer (--time)");
  if (c.design.required_flow_pattern != "any" && !arched && !out_bands.empty()) {
    if (order.label() == c.design.required_flow_pattern) verdict.pass("DEM flow pattern: " + order.label());
    else verdict.fail("DEM flow pattern " + order.label() + ", required " + c.design.required_flow_pattern);
  }
  record.verdict = verdict.verdict();

  Chart chart{"dem_discharged_mass_vs_time", "Cumulative discharged mass against time (DEM)",
              {"time after opening", "s"}, {"discharged mass", "kg"}, {}, ""};
  ChartSeries dem{"DEM slab x " + format("%.4g", scale), SeriesStyle::line, {}, {}, {}, -1};
  for (const auto& r : result.series.rows()) {
    dem.x.push_back(r[1]);
    dem.y.push_back(r[2] * scale);
  }
  chart.series.push_back(dem);
  if (const Estimate* q = find_result(record, reduced_model_key("mass_flow_rate")); q && q->is_number() && !dem.x.empty()) {
    const double qr = std::get<double>(q->value);
    const double t0 = rate.found ? rate.window_start : 0.0;
    double m0 = 0.0;
    for (std::size_t k = 0; k < dem.x.size() && dem.x[k] <= t0; ++k) m0 = dem.y[k];
    ChartSeries line{"reduced model, steady", SeriesStyle::dashed, {t0, dem.x.back()},
                     {m0, m0 + qr * (dem.x.back() - t0)}, {}, -1};
    chart.series.push_back(line);
  }
  chart.note = "DEM masses scaled from the slab to the slot length (x " + format("%.4g", scale) + ")";
  record.charts.push_back(chart);

  auto& a = record.assumptions;
  a.push_back("quasi-2D slab instead of the 3D hopper: " + format("%.3g", scene.slab.depth * 1e3) +
              " mm deep, masses scaled by the slot length / slab depth; a one-layer slab is a disc "
              "packing, which the seed used too (it over-predicted q_m slightly)");
  a.push_back("walls: a finite triangle-mesh wedge and analytic bin planes with the particle-wall "
              "Table 2 set; the outlet is opened by removing the gate plane once the fill has "
              "settled (the rig slides its side walls up)");
  a.push_back("filling: rain-fall following the fill top, settled to 1 mm/s or 0.5 s, trimmed at "
              "H; particles are deleted 5 R below the outlet (their mass is booked)");
  a.push_back("the run ends when the steady rate's 95 % interval is within +-5 %, the hopper "
              "arches or empties, or the duration runs out: " +
              (result.stop_reason.empty() ? std::string("duration") : result.stop_reason));
  if (!scene.settings.law.normal.is<HystereticNonlinear2>())
    a.push_back("normal contact law " + contact_law_name(scene.settings.law) +
                " instead of the seed's hysteretic one ([dem] normal_law)");
  if (!scene.fill.settled) a.push_back("the fill had not settled below 1 mm/s when the gate opened");
  return outcome;
}

}  // namespace feedflow
