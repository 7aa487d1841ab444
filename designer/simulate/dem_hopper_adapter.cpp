#include "designer/simulate/dem_hopper_adapter.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <optional>

#include "designer/simulate/dem_case_settings.hpp"
#include "designer/simulate/dem_hopper_scene.hpp"
#include "designer/simulate/hopper_discharge.hpp"
#include "designer/simulate/reduced_model_beside.hpp"
#include "fullsim/dem/scene/flow_order.hpp"
#include "fullsim/dem/scene/speed_profile.hpp"
#include "models/core/printf_format.hpp"
#include "reports/result_format.hpp"

namespace feedflow {
namespace {

constexpr double kHopperSampleInterval = 0.01;  // [s] time-series rows
namespace dem_hopper_column {
enum : std::size_t { kTime, kAfterOpening, kDischarged, kParticles, kMassInDomain, kKineticEnergy };
}  // namespace dem_hopper_column

HopperDischarge::Rows rows_of(const TimeSeries& s) {
  return discharge_rows(s, dem_hopper_column::kAfterOpening, dem_hopper_column::kDischarged,
                        dem_hopper_column::kMassInDomain, dem_hopper_column::kKineticEnergy);
}

Estimate number(double v, const std::string& unit, std::optional<double> lo, std::optional<double> hi,
                const std::string& model) {
  return Estimate{v, unit, lo, hi, model, Rung::L3, ""};
}

class DemHopperAdapter final : public SceneAdapter {
 public:
  explicit DemHopperAdapter(const SimulationRequest& request)
      : request_(request), scene_(hopper_scene_from_case(request.case_data)) {
    scene_.settings.ranks = request.ranks;
    // The rows' time axis is the time after the opening.
    discharge_.trickle_rate =
        discharge_.arch.trickle_share * scene_.outlet_rate_scale(request.case_data.material.bulk.density);
    if (!scene_.slab())
      discharge_.scale_rate = scene_.scale() == 1.0 ? "rho_b pi/4 D^2 sqrt(g D)" : "rho_b pi/4 D^2 sqrt(g D) x the sector's share";
  }

  std::string what() const override { return "the hopper"; }

  bool restore_fill(const Hdf5File& f) override {
    if (!RainFill::saved_in(f)) return false;
    restore_hopper_fill(scene_, engine(), f);
    return fill_restored_ = true;
  }
  bool save_fill(Hdf5File& f) const override { return engine_ && save_hopper_fill(scene_, *engine_, f); }

  Stepper* build(std::ostream& log, ProgressSink& progress) override {
    describe_hopper_scene(scene_, log);
    if (!request_.restart.empty() && !fill_restored_) return &engine();
    return fill_hopper_scene(scene_, engine(), &progress, log) ? &engine() : nullptr;
  }

  std::vector<TimeSeriesColumn> columns() const override {
    // time: the simulation time, as the particle snapshots and the checkpoint have it.
    return {{"time", "s"},          {"time_after_opening", "s"}, {"discharged_mass", "kg"},
            {"particles_in_domain", ""}, {"mass_in_domain", "kg"},    {"kinetic_energy", "J"}};
  }

  void restore(const Hdf5File& f) override {
    restore_hopper_scene(scene_, f);
    flow_line_.restore(f, "/scene/flow_line");
  }

  // The fill at the opening (a restored run: as saved).
  double fill_mass() const { return scene_.fill.inserted_mass - scene_.fill.trimmed_mass - scene_.fill.sunk_mass; }

  void plan(SceneRunOptions& run) override {
    run.label = "DEM hopper";
    run.origin = run.sample_origin = scene_.opening_time;
    run.duration = request_.end_time.value_or(scene_.default_duration);
    run.sample_interval = kHopperSampleInterval;
    run.snapshot_interval =
        dem_snapshot_interval(request_.case_data, run.duration, kHopperSampleInterval);
    run.sample = [this] {
      const DemEngine& e = *engine_;
      const double t_open = scene_.opening_time;
      const double out = e.sunk(t_open).mass;
      const BedView bed = e.bed();
      flow_line_.add(e.time() - t_open, flow_line(bed));
      return std::vector<double>{e.time(), e.time() - t_open, out, bed.count(), bed.total_mass(),
                                 e.kinetic_energy()};
    };
    discharge_.fill_mass = fill_mass();
    if (!request_.end_time)  // a given --time is run to its end
      run.stop = [this](const TimeSeries& s) { return discharge_.stop_reason(rows_of(s)); };
    run.save_scene = [this](Hdf5File& f) {
      save_hopper_scene(scene_, f);
      flow_line_.save(f, "/scene/flow_line");
    };
  }

  void measure(const SceneRunResult& run, DesignRecord& record) override {
    const double scale = scene_.scale();
    const double t_open = scene_.opening_time;
    const BedView bed = engine_->bed();
    const DemEngine::SunkTally sunk = engine_->sunk();
    log_mass_book(sunk.mass, bed.total_mass());
    const double discharged = sunk.mass - scene_.fill.sunk_mass;
    const double last = engine_->sunk(t_open).last;
    DischargeWording w{Rung::L3, scale, scene_.model_text(), "",
                       format("; arched: %.4g kg (scaled) left before the last exit at %.3g s after the opening",
                              discharged * scale, std::max(0.0, last - t_open)),
                       "DEM", "DEM; " + describe_flow_pattern(), "particle speeds", 0.0};
    const SteadyRate rate = add_discharge_results(discharge_, rows_of(run.series), flow_line_, w, record);
    auto& results = record.results;
    if (rate.found && scene_.slab())
      results.emplace_back("mass_flow_rate_slab", number(rate.rate, "kg/s", rate.low, rate.high,
                                                         "DEM slab as simulated (before the depth scaling)"));
    else if (rate.found && scale != 1.0)
      results.emplace_back("mass_flow_rate_sector", number(rate.rate, "kg/s", rate.low, rate.high,
                                                           "DEM sector as simulated (before the scaling to the whole cone)"));
    const FlowOrder order = layer_order(bed);
    results.emplace_back("fifo_index", Estimate{order.fifo_index, "", std::nullopt, std::nullopt,
                                                format("layer bands: pairs from different bands leaving in band order "
                                                       "(%d bands; %s by F >= %.2f)",
                                                       scene_.bands, order.label().c_str(), kMassFlowFifoIndex),
                                                Rung::L3, ""});
    results.emplace_back("discharged_mass", number(discharged * scale, "kg", std::nullopt, std::nullopt, scene_.model_text()));
    // The rate scales with the bed's density, which the spheres' packing sets, not the
    // material's bulk density the continuum and the reduced rung fill at.
    results.emplace_back(
        "fill_bulk_density",
        number(fill_mass() / scene_.filled_volume(), "kg/m^3", std::nullopt, std::nullopt,
               format("the DEM fill at the opening over the volume below the fill height (the "
                      "material's bulk density: %.4g kg/m^3; the rate scales with the bed's)",
                      request_.case_data.material.bulk.density)));
    results.emplace_back("simulated_time_after_opening",
                         number(engine_->time() - t_open, "s", std::nullopt, std::nullopt,
                                run.end == RunEnd::stopped ? run.stop_reason : "the run's duration"));
    if (const std::string w = engine_->spring_warning(); !w.empty()) record.verdict.reasons.push_back(w);
  }

  std::vector<std::string> reduced_model_quantities() const override {
    return {"mass_flow_rate", "critical_outlet_width", "flow_pattern"};
  }

  void explain(const SceneRunResult& run, DesignRecord& record) override {
    const double scale = scene_.scale();
    const char* part = scene_.slab() ? "slab" : "sector";
    Chart chart{"dem_discharged_mass_vs_time", "Cumulative discharged mass against time (DEM)",
                {"time after opening", "s"}, {"discharged mass", "kg"}, {}, ""};
    ChartSeries dem{scale == 1.0 ? std::string("DEM") : format("DEM %s x %.4g", part, scale), SeriesStyle::line, {}, {}, {}, -1};
    for (const auto& r : run.series.rows()) {
      dem.x.push_back(r[dem_hopper_column::kAfterOpening]);
      dem.y.push_back(r[dem_hopper_column::kDischarged] * scale);
    }
    chart.series.push_back(dem);
    const SteadyRate rate = discharge_.steady_rate(rows_of(run.series));
    if (const Estimate* q = find_estimate(record.results, reduced_model_key("mass_flow_rate")); q && q->is_number() && !dem.x.empty()) {
      const double qr = std::get<double>(q->value);
      const double t0 = rate.found ? rate.window_start : 0.0;
      double m0 = 0.0;
      for (std::size_t k = 0; k < dem.x.size() && dem.x[k] <= t0; ++k) m0 = dem.y[k];
      chart.series.push_back({"reduced model, steady", SeriesStyle::dashed, {t0, dem.x.back()},
                              {m0, m0 + qr * (dem.x.back() - t0)}, {}, -1});
    }
    chart.note = scene_.slab() ? format("DEM masses scaled from the slab to the slot length (x %.4g)", scale)
                 : scale == 1.0 ? std::string("DEM of the whole cone")
                                : format("DEM masses scaled from the sector to the whole cone (x %.4g)", scale);
    record.charts.push_back(chart);

    auto& a = record.assumptions;
    if (const WedgeHopperSlab* slab = scene_.slab()) {
      a.push_back("quasi-2D slab instead of the 3D hopper: " + format("%.3g", slab->depth * 1e3) +
                  " mm deep, masses scaled by the slot length / slab depth; a one-layer slab is a disc "
                  "packing, which the seed used too (it over-predicted q_m slightly)");
      a.push_back("walls: a finite triangle-mesh wedge and analytic bin planes with the particle-wall "
                  "Table 2 set; the outlet is opened by removing the gate plane once the fill has "
                  "settled (the rig slides its side walls up)");
      a.push_back("slab faces ([dem] slab_faces): " + slab->describe_faces());
    } else {
      a.push_back("conical hopper in 3D: " + std::get<ConicalHopper>(scene_.geometry).simulated_part() +
                  " ([dem] sector_angle)");
      a.push_back("walls: a triangle-mesh cone (facets within R/20 of the true cone) and an analytic "
                  "cylindrical bin with the particle-wall Table 2 set; the outlet is opened by removing "
                  "the gate plane once the fill has settled");
    }
    a.push_back("filling: rain-fall following the fill top, settled to 1 mm/s or 0.5 s, trimmed at "
                "H; particles are deleted 5 R below the outlet (their mass is booked)");
    a.push_back("the run ends when the steady rate's 95 % interval is within +-5 %, the hopper "
                "arches or empties, or the duration runs out: " +
                (run.end == RunEnd::stopped ? run.stop_reason : std::string("duration")));
    a.push_back("flow pattern as on every rung: " + describe_flow_pattern() + "; the layer bands' first-in-"
                "first-out index is reported beside it");
    if (!scene_.settings.law.normal.is<HystereticNonlinear2>())
      a.push_back("normal contact law " + contact_law_name(scene_.settings.law) +
                  " instead of the seed's hysteretic one ([dem] normal_law)");
    if (!scene_.fill.settled) a.push_back("the fill had not settled below 1 mm/s when the gate opened");
    add_time_step_warning(*engine_, a);
  }

 private:
  // The slab's structure (walls, wedge, sink): filled by build, or restored into.
  DemEngine& engine() {
    if (!engine_) engine_.emplace(hopper_scene_structure(scene_));
    return *engine_;
  }

  // The order of the bands (each particle's layer, set at the trim): of the particles in the
  // order they left (the sink's books, merged once), and of those left in the hopper (counts
  // per band, summed over the ranks).
  FlowOrder layer_order(const BedView& bed) const {
    std::vector<int> out_bands;
    const OutletSink sink = *engine_->merged_outlet_sink();
    for (const auto& ev : sink.events())
      if (ev.time > scene_.opening_time && std::isfinite(ev.layer))
        out_bands.push_back(static_cast<int>(ev.layer));
    const ParticleStore& p = bed.store();
    double low = std::numeric_limits<double>::infinity(), high = -low;  // the bands present
    for (std::size_t k = 0; k < bed.own(); ++k) {
      low = std::min(low, p.layer[k]);
      high = std::max(high, p.layer[k]);
    }
    low = -bed.max(-low);
    high = bed.max(high);
    std::map<int, double> left_bands;
    if (low <= high) {
      std::vector<double> left(static_cast<std::size_t>(high - low) + 1, 0.0);
      for (std::size_t k = 0; k < bed.own(); ++k) left[static_cast<std::size_t>(p.layer[k] - low)] += 1.0;
      bed.sum(left);
      for (std::size_t b = 0; b < left.size(); ++b)
        if (left[b] > 0.0) left_bands[static_cast<int>(low) + static_cast<int>(b)] = left[b];
    }
    return flow_order_by_counts(out_bands, left_bands);
  }

  // The particle speeds along the flow-pattern line now (of every rank's particles).
  SpeedProfile flow_line(const BedView& bed) const {
    const double r = scene_.radius();
    return speed_profile(bed, 0.5 * scene_.transition_height(), 2.0 * r, 2.0 * r, scene_.profile_offset());
  }

  std::string describe_flow_pattern() const {
    const double r = scene_.radius();
    return format("mass flow when the speed beside the wall is above %.2g of the centre line's, at mid-height of "
                  "the converging section over the steady window (z = %.3g m; particles within %.3g mm of it, "
                  "bins of %.3g mm)",
                  kMassFlowSpeedRatio, 0.5 * scene_.transition_height(), 2e3 * r, 2e3 * r);
  }

  void log_mass_book(double sunk, double in_domain) const {
    if (!request_.log) return;
    const double booked = in_domain + sunk + scene_.fill.trimmed_mass;
    *request_.log << format("mass book: inserted %.9g kg = in the domain %.9g kg + through the sink %.9g kg + "
                            "trimmed %.9g kg (difference %.3g kg)\n",
                            scene_.fill.inserted_mass, in_domain, sunk, scene_.fill.trimmed_mass,
                            booked - scene_.fill.inserted_mass);
  }

  const SimulationRequest& request_;
  DemHopperScene scene_;
  std::optional<DemEngine> engine_;  // made at the first use
  bool fill_restored_ = false;
  HopperDischarge discharge_;
  SpeedProfileSeries flow_line_;  // sampled on the rows' time axis (after the opening)
};

}  // namespace

std::unique_ptr<SceneAdapter> dem_hopper_adapter(const SimulationRequest& request) {
  return std::make_unique<DemHopperAdapter>(request);
}

}  // namespace feedflow
