#include "designer/simulate/cel_hopper_adapter.hpp"

#include <cmath>
#include <limits>
#include <numbers>

#include "designer/simulate/cel_scene_adapter.hpp"
#include "designer/simulate/hopper_discharge.hpp"
#include "fullsim/cel/hopper_scene.hpp"
#include "fullsim/cel/scene_measurements.hpp"
#include "models/core/errors.hpp"
#include "models/units/quantity_format.hpp"

namespace feedflow {
namespace {

namespace cel_hopper_column {
enum : std::size_t { kTime, kDischarged, kMassInHopper, kKineticEnergy };
}  // namespace cel_hopper_column

const Hopper& hopper_of(const SimulationRequest& r) { return std::get<Hopper>(r.case_data.equipment); }

cel::HopperSection section_of(const Case& c) {
  return c.cel.hopper_section == "full" ? cel::HopperSection::full : cel::HopperSection::half;
}

cel::CelScene hopper_scene(const SimulationRequest& request) {
  const Case& c = request.case_data;
  const Hopper& hopper = hopper_of(request);
  if (!hopper.is_wedge() && c.cel.hopper_section == "full")
    throw InputError(c.file, "cel.hopper_section",
                     "a conical hopper runs axisymmetric about its axis; \"full\" (the full-width "
                     "plane section) is for wedge hoppers: leave the key out");
  if (!hopper.is_wedge() && c.cel.mixed_cells == "void_first")
    throw InputError(c.file, "cel.mixed_cells",
                     "\"void_first\" does not settle a conical hopper's fill on the axisymmetric grid (its kinetic "
                     "energy stays up through the gravity phase): leave the key out (equal_strain_rate)");
  const double phi_w = hopper.wall_friction_angle.value_or(c.material.bulk.wall_friction_angle);
  const double cell = cel_cell_size(c, default_hopper_cell_size(hopper.outlet_width));
  const double across = 0.5 * hopper.outlet_width / cell;
  // 1 % slack: a cell size typed rounded (6.67 mm for 3 cells across 20 mm) is not refused.
  if (across < kMinimumCellsAcrossHalfOutlet * 0.99)
    throw InputError(c.file, "cel.cell_size",
                     format_quantity(cell, "mm") + " puts " + format_number(across, 2) + " cells across the half outlet (" +
                         format_quantity(0.5 * hopper.outlet_width, "mm") + "); the CEL hopper needs at least " +
                         format_number(kMinimumCellsAcrossHalfOutlet, 2) +
                         " (feedflow bench: the 60 mm pilot hopper reads \"arched\" on 1.5 cells though it flows): use at "
                         "most " +
                         format_quantity(0.5 * hopper.outlet_width / kMinimumCellsAcrossHalfOutlet, "mm"));
  try {
    return cel::make_hopper_scene(hopper, phi_w, scene_material(c), cell, section_of(c));
  } catch (const std::invalid_argument& e) {
    throw InputError(c.file, "hopper", e.what());
  }
}

class CelHopperAdapter final : public CelSceneAdapter {
 public:
  explicit CelHopperAdapter(const SimulationRequest& request)
      : CelSceneAdapter(request, hopper_scene(request), 0.01),
        hopper_(hopper_of(request)),
        section_(section_of(request.case_data)),
        slot_(hopper_.slot_length.value_or(1.0)) {
    const double w = hopper_.outlet_width;
    discharge_.trickle_rate = discharge_.arch.trickle_share * outlet_scale_rate(request.case_data.material.bulk.density, w) *
                              (cone() ? 0.25 * std::numbers::pi * w : slot_);
    if (cone()) {
      discharge_.scale_rate = "rho_b pi/4 D^2 sqrt(g D)";
      // The pilot cone's rate climbs for about 1 s after the opening (0.50 kg/s over 0.1-0.6 s,
      // 0.64 over 0.65-2.15 s at 10 mm and 5 mm, tests/benchmarks/RECORD.md): no earlier stop.
      discharge_.earliest_convergence = 2.0;
    }
  }

  std::vector<TimeSeriesColumn> columns() const override {
    return {{"time", "s"}, {"discharged_mass", "kg"}, {"mass_in_hopper", "kg"}, {"kinetic_energy", "J"}};
  }

  std::string stop(const TimeSeries& series) const override {
    if (run().phase() != cel::ScenePhase::event) return {};
    return discharge(series).stop_reason(rows_of(series));
  }

  void plan(SceneRunOptions& run_options) override {
    CelSceneAdapter::plan(run_options);
    run_options.save_scene = [this](Hdf5File& f) { flow_line_.save(f, "/scene/flow_line"); };
  }

  void restore(const Hdf5File& f) override { flow_line_.restore(f, "/scene/flow_line"); }

  std::vector<double> sample() override {
    const double depth = run().scene().section_depth_factor * slot_;  // kg/m (kg/rad) of the section -> kg
    const auto& s = run().solver();
    if (run().phase() == cel::ScenePhase::event) flow_line_.add(s.time(), flow_line());
    return {s.time(), depth * s.discharge().total(), depth * s.total_mass(), depth * s.kinetic_energy()};
  }

  void measure(const SceneRunResult& result, DesignRecord& record) override {
    add_throughput(record);
    if (!reached_event(record)) return;
    const cel::CelSolver& s = run().solver();
    const double t_event = run().event_time();
    const double f = run().scene().section_depth_factor;
    const std::string& label = model_label();
    const DischargeWording w{Rung::L2, 1.0, label + ", " + section_text() + (cone() ? "" : ", x slot length " + format_quantity(slot_, "m", 3)),
                             " (times from the start of the run)", "; arched", label, label, "node speeds", t_event};
    const SteadyRate q = add_discharge_results(discharge(result.series), rows_of(result.series), flow_line_, w, record);
    auto& results = record.results;
    if (q.found && !cone())
      results.emplace_back("mass_flow_rate_per_metre",
                           Estimate{q.rate / slot_, "kg/s/m", q.low / slot_, q.high / slot_, label + ", " + section_text(),
                                    Rung::L2, ""});
    results.emplace_back("discharged_mass", Estimate{f * s.discharge().total() * slot_, "kg", std::nullopt,
                                                     std::nullopt, label + ", " + section_text() + (cone() ? "" : ", x slot length"),
                                                     Rung::L2, ""});
    results.emplace_back("simulated_time_after_opening",
                         Estimate{s.time() - t_event, "s", std::nullopt, std::nullopt,
                                  result.end == RunEnd::stopped ? result.stop_reason : "the run's duration", Rung::L2, ""});
    const double lost = (s.total_mass() + s.discharge().total() + s.removed_mass()) / run().initial_mass() - 1.0;
    results.emplace_back("mass_balance_error", Estimate{lost, "", std::nullopt, std::nullopt,
                                                        "(grid + discharged + cut off) / initial - 1", Rung::L2, ""});
    add_overfilled_share(record);
  }

  std::vector<std::string> reduced_model_quantities() const override {
    return {"mass_flow_rate", "flow_pattern", "critical_outlet_width"};
  }

  void explain(const SceneRunResult& run_result, DesignRecord& record) override {
    if (run().phase() == cel::ScenePhase::event) {
      const double t_event = run().event_time();
      Chart chart{"discharged_mass_vs_time", "Discharged mass against time (CEL-FEM)", {"time after opening", "s"},
                  {"discharged mass", "kg"}, {}, ""};
      ChartSeries series{"CEL-FEM", SeriesStyle::line, {}, {}, {}, -1};
      for (const auto& row : run_result.series.rows())
        if (row[0] >= t_event) series.x.push_back(row[0] - t_event), series.y.push_back(row[1]);
      chart.series.push_back(series);
      chart.note = "Ledger of the outflow face, scaled from the " + section_text() +
                   (cone() ? " to the whole cone." : " to the slot length.");
      record.charts.push_back(chart);
    }
    const std::string& label = model_label();
    record.assumptions = {
        cone()
            ? std::string(
                  "Axisymmetric (r, z) about the cone's axis: hoop strain rate and stress in the "
                  "element, "
                  "r-weighted volumes in the remap, the circular outlet on the axis; the rate per "
                  "radian "
                  "is multiplied by 2 pi. Swirl and flow off the axis' symmetry (asymmetric "
                  "arches, "
                  "rat-holes) are not represented. The flow pattern on this grid does not "
                  "converge: the pilot "
                  "cone's (8.5 deg walls) wall zone slows as the cells shrink: wall/centre speed "
                  "at 20 deg "
                  "0.69, 0.71, 0.38, at 30 deg 0.39, 0.23, 0.079 (mass flow turning to funnel "
                  "flow) and at "
                  "40 deg 0.14, 0.019, 0.007 at 10, 5 and 2.5 mm cells; funnel flow from 45 deg at "
                  "every size. At 30 deg on "
                  "1.25 mm cells the cone is in funnel flow (wall/centre 0.019, a 46 mm stagnant "
                  "band): the "
                  "band at the wall holds a ring arch, its hoop stress several times its in-plane "
                  "stresses. "
                  "Without wall friction the band fades on refinement (0.1 deg: wall share 0.35, "
                  "0.69 at "
                  "10, 5 mm), with the pine's 8.5 deg it stays (0.26, 0.21): the wall's friction "
                  "holds the "
                  "ring. It is the law's answer, not the staircase: with cut cells at the walls "
                  "(cel.wall_cells = cut) the 30 deg cone is in funnel flow on 2.5 and 1.25 mm "
                  "cells alike (a 30 and 38.75 mm band, q_m 0.410 and 0.407 kg/s), and on them the "
                  "continuum puts the boundary between 25 and 30 deg. "
                  "Arnold-McLean puts the limit "
                  "at 39.6 deg and the DEM near 47 deg: read the CEL's flow pattern on a cone as a "
                  "pessimistic indication, not an answer (design --verify does not use it). A "
                  "funnel-flow "
                  "channel follows the grid's columns and runs fast on coarse cells (45 deg: 0.62 "
                  "kg/s at "
                  "10 mm, 0.45 kg/s at 5 mm).")
            : std::string(
                  section_ == cel::HopperSection::full
                      ? "Plane strain full-width section, both walls ([cel] hopper_section = "
                        "full): the rate per metre is "
                      : "Plane strain half slice with a symmetry plane, as the seed's FEM ([cel] "
                        "hopper_section = half): the half slice's rate per metre is doubled and ") +
                  "multiplied by the slot length " + format_quantity(slot_, "m", 3) +
                  (hopper_.slot_length ? "" : " (assumed 1 m: the case gives no slot length)") +
                  "; end walls of the slot are not modelled (errs high for short slots).",
        "Initial void ratio 0.7102 (seed deck) at the case's bulk density; initial stress -10 Pa "
        "I.",
        "Remap: " + label.substr(label.find(", ") + 2, label.size() - label.find(", ") - 3) +
            " ([cel] remap_order, material_flux; the donor cell smears the free surface and the "
            "outlet jet); q_m from the exact outflow ledger. Cut cells fill whole: up to half a "
            "cell of material behind the walls; cells at the walls' staircase that overfill keep "
            "their void ratio and pass the excess on (not compacted). That excess is mass without "
            "pressure moving along the wall (overfilled_mass_share): about 14 % of the grid's mass "
            "by the end in the pilot cone (mass flow along a 20 deg wall), 2 % in the pilot wedge.",
        cone()
            ? "q_m depends on the cell size; the axisymmetric cone is not on the bench: the pilot "
              "cone gives "
              "0.483 kg/s at 10 mm cells (3 across the orifice's radius) against 0.505 kg/s at 5 "
              "mm."
            : "q_m depends on the cell size: pilot hopper 5.29 kg/s at 10 mm cells (outlet 3 cells "
              "across the half slot) against 5.49 kg/s at 5 mm (1 s after the opening); at 20 mm "
              "(1.5 "
              "cells) it arches.",
        "Gravity phase with dynamic relaxation (damping switched off at the opening); not "
        "physical, "
        "it only brings the fill to rest faster.",
        "Measured as on every rung: q_m over the steady window of 50 ms batches (MSER, 95 % "
        "batch-means "
        "interval); \"arched\" when less than 2 % of rho_b W sqrt(g W) leaves for 0.5 s and the "
        "bed is "
        "still; flow pattern: mass flow when the wall-side node moves at more than 10 % of the "
        "centreline speed at mid-height of the converging section, averaged over the steady "
        "window.",
        "No cohesion in the hypoplastic law: a continuum arch is frictional only (errs toward "
        "flow)."};
  }

 private:
  bool cone() const { return !hopper_.is_wedge(); }
  std::string section_text() const {
    if (cone()) return "about the axis, x 2 pi";
    return section_ == cel::HopperSection::full ? "full-width section" : "half slice (symmetry plane, x 2)";
  }

  // The discharge rule with this run's fill (known once the scene is built).
  HopperDischarge discharge(const TimeSeries& series) const {
    HopperDischarge d = discharge_;
    d.opening = run().event_time();
    d.fill_mass = series.empty() ? 0.0 : run().initial_mass() * run().scene().section_depth_factor * slot_;
    return d;
  }

  // The node speeds along the flow-pattern line now.
  SpeedProfile flow_line() const {
    const double knee = (0.5 * hopper_.bin_width - 0.5 * hopper_.outlet_width) / std::tan(hopper_.semi_angle);
    return cel::speed_profile(run().solver(), 0.5 * knee, cel::hopper_centre_line(hopper_, section_));
  }

  HopperDischarge::Rows rows_of(const TimeSeries& series) const {
    return discharge_rows(series, cel_hopper_column::kTime, cel_hopper_column::kDischarged,
                          cel_hopper_column::kMassInHopper, cel_hopper_column::kKineticEnergy);
  }

  const Hopper& hopper_;
  cel::HopperSection section_;
  double slot_;
  HopperDischarge discharge_;
  SpeedProfileSeries flow_line_;  // sampled after the opening, on the run's time axis
};

}  // namespace

double default_hopper_cell_size(double outlet_width) {
  return std::min(0.01, 0.5 * outlet_width / kMinimumCellsAcrossHalfOutlet);
}

std::unique_ptr<SceneAdapter> cel_hopper_adapter(const SimulationRequest& request) {
  return std::make_unique<CelHopperAdapter>(request);
}

}  // namespace feedflow
