#include "designer/simulate/cel_chute_simulation.hpp"

#include <algorithm>
#include <cmath>

#include "designer/design/verdict_builder.hpp"
#include "designer/simulate/cel_scene_driver.hpp"
#include "designer/simulate/reduced_model_beside.hpp"
#include "fullsim/cel/chute_scene.hpp"
#include "fullsim/cel/scene_measurements.hpp"
#include "models/units/quantity_format.hpp"

namespace feedflow {
namespace {

constexpr double kRestRatio = 1e-4;  // kinetic energy below this x its peak after the release
constexpr int kKineticColumn = 1, kProbeColumn = 4;

// Mean thickness of the three columns around x (sum of h x volume fraction) [m].
double thickness_at(const cel::CelSolver& s, double x) {
  const auto t = cel::column_thickness(s);
  const int i = static_cast<int>((x - s.grid().origin.x()) / s.grid().cell_size);
  double sum = 0.0;
  int n = 0;
  for (int k = std::max(0, i - 1); k <= std::min(s.grid().nx - 1, i + 1); ++k) sum += t[k], ++n;
  return n ? sum / n : 0.0;
}

}  // namespace

SimulationOutcome simulate_chute_with_cel(const SimulationRequest& request) {
  const Case& c = request.case_data;
  const std::string model_label = cel_model_label(c);
  const Chute& chute = std::get<Chute>(c.equipment);
  const double h = cel_cell_size(c, 0.02);
  CelRunSetup setup;
  setup.scene = cel::make_chute_scene(chute, scene_material(c), h);
  setup.model = cel_material_model(c);
  const double ramp_start = chute.bin_length + 2.0 * h;
  const double mid = ramp_start + 0.5 * chute.length;
  const double width = chute.width;
  setup.sample_interval = 0.02;
  setup.sample = [mid, width](const cel::CelSceneRun& run) {
    const auto& s = run.solver();
    return std::vector<double>{s.time(), width * s.kinetic_energy(), width * s.total_mass(),
                               width * s.discharge().total(), thickness_at(s, mid)};
  };
  setup.finished = [](const cel::CelSceneRun& run, const std::vector<std::vector<double>>& rows) {
    if (run.phase() != cel::ScenePhase::event || run.solver().time() < run.event_time() + 1.0)
      return false;
    double peak = 0.0;
    for (const auto& row : rows)
      if (row[0] >= run.event_time()) peak = std::max(peak, row[kKineticColumn]);
    return rows.back()[kKineticColumn] < kRestRatio * peak;
  };
  CelRunResult r = run_cel_scene(request, std::move(setup));
  const cel::CelSceneRun& run = *r.run;
  const cel::CelSolver& s = run.solver();

  SimulationOutcome out = outcome_of(r, {{"time", "s"}, {"kinetic_energy", "J"}, {"mass_on_grid", "kg"},
                           {"run_off_mass", "kg"}, {"thickness_mid_ramp", "m"}});
  DesignRecord& rec = out.record;
  VerdictBuilder verdict;
  if (run.phase() == cel::ScenePhase::event) {
    const double h_mid = thickness_at(s, mid);
    // Band: the thickness over the middle fifth of the ramp.
    const auto t = cel::column_thickness(s);
    double lo = h_mid, hi = h_mid;
    Chart chart{"deposit_profile", "Deposit thickness along the ramp (CEL-FEM)",
                {"distance along the ramp from the gate", "m"}, {"thickness", "mm"}, {}, ""};
    ChartSeries series{"CEL-FEM, end of run", SeriesStyle::line, {}, {}, {}, -1};
    for (int i = 0; i < s.grid().nx; ++i) {
      const double x = s.grid().origin.x() + (i + 0.5) * h;
      if (x < ramp_start) continue;
      series.x.push_back(x - ramp_start);
      series.y.push_back(t[i] * 1e3);
      if (std::abs(x - mid) <= 0.1 * chute.length) lo = std::min(lo, t[i]), hi = std::max(hi, t[i]);
    }
    chart.series.push_back(series);
    chart.note = "Sum of cell heights x volume fraction per column (the seed's FEM measure).";
    rec.charts.push_back(chart);
    rec.results.emplace_back("deposit_thickness_mid_ramp",
                             Estimate{h_mid, "m", lo, hi,
                                      model_label + "; band over the middle fifth of the ramp",
                                      Rung::L2, "mm"});
    rec.results.emplace_back("at_rest", Estimate{r.finished_early ? "yes" : "no (time limit)", "",
                                                 std::nullopt, std::nullopt,
                                                 "kinetic energy below 1e-4 x its peak", Rung::L2, ""});
    rec.results.emplace_back("time_to_rest",
                             Estimate{s.time() - run.event_time(), "s", std::nullopt, std::nullopt,
                                      r.finished_early ? "from the gate release" : "run length (not at rest)",
                                      Rung::L2, ""});
    const double m0 = run.initial_mass();
    rec.results.emplace_back("fraction_leaving_ramp",
                             Estimate{100.0 * s.discharge().total() / m0, "%", std::nullopt,
                                      std::nullopt, model_label, Rung::L2, ""});
    if (!r.finished_early)
      verdict.note("the flow had not come to rest when the run ended: the deposit is an upper bound");
    if (c.design.max_stopping_thickness)
      verdict.judge_at_least(*c.design.max_stopping_thickness - h_mid,
                             *c.design.max_stopping_thickness - hi, 0.0);
    else
      verdict.note("simulated deposit at mid-ramp " + format_quantity(h_mid, "mm", 3));
  } else {
    verdict.note("the run ended in the gravity phase: nothing measured");
  }
  add_throughput_result(r, rec);
  add_reduced_model_results(c, {"stopping_thickness", "deposit_thickness_mid_ramp"}, rec);
  rec.verdict = verdict.verdict();
  rec.assumptions = {
      "Plane-strain slice along the ramp centre line: no side walls, no lateral spill (the "
      "seed's FEM was 3D half-symmetric); errs thick where the real deposit spreads sideways.",
      "Ramp no slip (chips glued on), bin back wall and gate free slip; the bin floor is the ramp "
      "and the gate moves normal to it, lifted at 1 m/s (speed assumed).",
      "Initial void ratio 0.7102 (seed deck) at the case's bulk density; no cohesion in the "
      "hypoplastic law.",
      "h at mid-ramp = sum of cell heights x volume fraction (seed FEM), mean of three columns."};
  return out;
}

}  // namespace feedflow
