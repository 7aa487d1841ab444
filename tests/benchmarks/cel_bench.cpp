// CEL-FEM throughput: cell updates per second (time-step pass + Lagrangian phase + hypoplastic
// update + donor-cell remap) for a settled pine column of 100 x 100 cells (h = 10 mm) in a
// 100 x 110 grid with free-slip walls. The column starts in the geostatic K0 state
// (sigma_v = -rho g depth, sigma_h = K0 sigma_v), so it is at rest from the first step.
// Argument 0: plane strain; 1: the same grid axisymmetric about its left face (a cylinder of
// radius 1 m; the hoop terms and r-weighted volumes are the only difference in the work).
#include <benchmark/benchmark.h>

#include "fullsim/cel/cel_solver.hpp"

namespace {

using namespace feedflow;
using namespace feedflow::cel;

void CelSettledColumnStep(benchmark::State& state) {
  const double h = 0.01, width = 1.0, height = 1.0, rho = 290.0, k0 = 0.35;
  CelOptions o;
  o.walls = {WallCondition::free_slip, WallCondition::free_slip, WallCondition::free_slip,
             WallCondition::open};
  const bool axisymmetric = state.range(0) == 1;
  CelSolver solver(axisymmetric ? make_axisymmetric_grid(100, 110, h) : make_plane_strain_grid(100, 110, h),
                   make_hypoplastic_model(loblolly_pine_table1()), o);
  for (int j = 0; j < 100; ++j) {  // one row at a time, in its geostatic state
    const double depth = height - (j + 0.5) * h;
    const double sv = -rho * 9.81 * depth - 10.0;
    MaterialBlock row{{0.0, j * h}, {width, (j + 1) * h}, rho, 0.7102,
                      Eigen::Vector3d(k0 * sv, sv, k0 * sv).asDiagonal()};
    solver.add_material(row);
  }
  for (int k = 0; k < 20; ++k) solver.step();  // past the start-up
  const long updates0 = solver.cell_updates();
  for (auto _ : state) solver.step();
  const double updates = static_cast<double>(solver.cell_updates() - updates0);
  state.counters["cell_updates_per_s"] = benchmark::Counter(updates, benchmark::Counter::kIsRate);
  state.counters["active_cells"] = static_cast<double>(solver.active_cells().size());
  state.counters["dt_us"] = solver.last_dt() * 1e6;
  state.SetLabel(axisymmetric ? "axisymmetric" : "plane strain");
}
BENCHMARK(CelSettledColumnStep)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->MinTime(2.0)->UseRealTime();

}  // namespace
