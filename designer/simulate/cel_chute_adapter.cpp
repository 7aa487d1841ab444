#include "designer/simulate/cel_chute_adapter.hpp"

#include <algorithm>
#include <cmath>

#include "designer/simulate/cel_scene_adapter.hpp"
#include "fullsim/cel/chute_scene.hpp"
#include "fullsim/cel/scene_measurements.hpp"
#include "fullsim/common/deposit_measurement.hpp"

namespace feedflow {
namespace {

constexpr double kRestRatio = 1e-4;  // kinetic energy below this x its peak after the release
namespace cel_chute_column {
enum : std::size_t { kTime, kKineticEnergy, kMassOnGrid, kRunOff, kThicknessMidRamp };
}  // namespace cel_chute_column

const Chute& chute_of(const SimulationRequest& r) { return std::get<Chute>(r.case_data.equipment); }

// The column thickness along the ramp: distance from the gate and sum of h x volume fraction.
struct RampProfile {
  std::vector<double> x, thickness;  // [m]
};

RampProfile ramp_profile(const cel::CelSolver& s, double ramp_start) {
  const auto t = cel::column_thickness(s);
  RampProfile p;
  for (int i = 0; i < s.grid().nx; ++i) {
    const double x = s.grid().origin.x() + (i + 0.5) * s.grid().cell_size;
    if (x < ramp_start) continue;
    p.x.push_back(x - ramp_start);
    p.thickness.push_back(t[i]);
  }
  return p;
}

class CelChuteAdapter final : public CelSceneAdapter {
 public:
  explicit CelChuteAdapter(const SimulationRequest& request)
      : CelSceneAdapter(request,
                        cel::make_chute_scene(chute_of(request), scene_material(request.case_data),
                                              cel_cell_size(request.case_data, kCelChuteCellSize)),
                        kCelChuteCellSize),
        chute_(chute_of(request)),
        ramp_start_(chute_.bin_length + 2.0 * cel_cell_size(request.case_data, kCelChuteCellSize)) {
  }

  std::vector<TimeSeriesColumn> columns() const override {
    return {{"time", "s"}, {"kinetic_energy", "J"}, {"mass_on_grid", "kg"}, {"run_off_mass", "kg"},
            {"thickness_mid_ramp", "m"}};
  }

  std::vector<double> sample() override {
    const auto& s = run().solver();
    const double width = chute_.width;
    return {s.time(), width * s.kinetic_energy(), width * s.total_mass(), width * s.discharge().total(),
            deposit().value};
  }

  std::string stop(const TimeSeries& series) const override {
    if (run().phase() != cel::ScenePhase::event || run().solver().time() < run().event_time() + 1.0) return {};
    double peak = 0.0;
    for (const auto& row : series.rows())
      if (row[cel_chute_column::kTime] >= run().event_time())
        peak = std::max(peak, row[cel_chute_column::kKineticEnergy]);
    return series.rows().back()[cel_chute_column::kKineticEnergy] < kRestRatio * peak
               ? "at rest: the kinetic energy is below 1e-4 of its peak after the release"
               : "";
  }

  void measure(const SceneRunResult& result, DesignRecord& record) override {
    add_throughput(record);
    if (!reached_event(record)) return;
    const cel::CelSolver& s = run().solver();
    const bool at_rest = !stop(result.series).empty();
    const DepositThickness h = deposit();
    auto& results = record.results;
    results.emplace_back("deposit_thickness_mid_ramp",
                         Estimate{h.value, "m", h.low, h.high,
                                  model_label() + "; sum of h x volume fraction per column, mean over mid-ramp +-5 % "
                                                  "(band: the columns' range)",
                                  Rung::L2, "mm"});
    results.emplace_back("at_rest", Estimate{at_rest ? "yes" : "no (time limit)", "", std::nullopt, std::nullopt,
                                             "kinetic energy below 1e-4 x its peak", Rung::L2, ""});
    results.emplace_back("time_to_rest", Estimate{s.time() - run().event_time(), "s", std::nullopt, std::nullopt,
                                                  at_rest ? "from the gate release" : "run length (not at rest)",
                                                  Rung::L2, ""});
    results.emplace_back("fraction_leaving_ramp",
                         Estimate{100.0 * s.discharge().total() / run().initial_mass(), "%", std::nullopt,
                                  std::nullopt, model_label(), Rung::L2, ""});
    if (!at_rest)
      record.verdict.reasons.push_back("the flow had not come to rest when the run ended: the deposit is an upper bound");
  }

  std::vector<std::string> reduced_model_quantities() const override {
    return {"stopping_thickness", "deposit_thickness_mid_ramp"};
  }

  void explain(const SceneRunResult&, DesignRecord& record) override {
    if (run().phase() == cel::ScenePhase::event) {
      const RampProfile p = ramp_profile(run().solver(), ramp_start_);
      Chart chart{"deposit_profile", "Deposit thickness along the ramp (CEL-FEM)",
                  {"distance along the ramp from the gate", "m"}, {"thickness", "mm"}, {}, ""};
      ChartSeries series{"CEL-FEM, end of run", SeriesStyle::line, p.x, {}, {}, -1};
      for (double t : p.thickness) series.y.push_back(t * 1e3);
      chart.series.push_back(series);
      chart.note = "Sum of cell heights x volume fraction per column (the seed's FEM measure).";
      record.charts.push_back(chart);
    }
    record.assumptions = {
        "Plane-strain slice along the ramp centre line: no side walls, no lateral spill (the "
        "seed's FEM was 3D half-symmetric); errs thick where the real deposit spreads sideways.",
        "Ramp no slip (chips glued on), bin back wall and gate free slip; the bin floor is the "
        "ramp and the gate moves normal to it, lifted at 1 m/s (speed assumed).",
        "Initial void ratio 0.7102 (seed deck) at the case's bulk density; no cohesion in the "
        "hypoplastic law.",
        "PLIC material flux unless [cel] material_flux names another: with the donor cell the "
        "deposit smears into a half-full cloud several cells deep.",
        "h at mid-ramp = sum of cell heights x volume fraction (seed FEM), measured as on every "
        "rung: the mean over the columns within 5 % of the ramp length of mid-ramp, the band "
        "their range."};
  }

 private:
  DepositThickness deposit() const {
    const RampProfile p = ramp_profile(run().solver(), ramp_start_);
    return mid_ramp_thickness(p.x, p.thickness, chute_.length);
  }

  const Chute& chute_;
  double ramp_start_;
};

}  // namespace

std::unique_ptr<SceneAdapter> cel_chute_adapter(const SimulationRequest& request) {
  return std::make_unique<CelChuteAdapter>(request);
}

}  // namespace feedflow
