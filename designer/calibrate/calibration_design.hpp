#pragma once
// The design of experiments of a discharge calibration: hopper points (outlet width x semi-angle,
// some held out of the fit) of one case, each answered by a full rung: CEL at cell sizes that
// put a fixed number of cells across the half outlet (so every point is resolved alike, and two
// or more levels extrapolate by Richardson), or DEM at the case's own resolution. Each point is
// a bench question, so runs are made, saved and read back by the bench's machinery.
#include <optional>
#include <string>
#include <vector>

#include "designer/bench/bench_plan.hpp"
#include "designer/bench/measured_bench.hpp"

namespace feedflow {

struct DesignPoint {
  double outlet_width;  // [m]
  double semi_angle;    // [rad]
  bool held_out;        // left out of the fit, to test it
};

// The order the hopper's CEL discharge rate converges with, as `feedflow bench` measured it
// (the shipped table's pilot hopper question: 10, 5, 2.5 mm at W = 60 mm), and where it was
// measured: what two levels extrapolate with unless told otherwise; at most the donor-cell
// remap's formal order 1, which is also taken when the levels showed no order. Throws
// NotAvailable when the table has no reference for it.
struct MeasuredOrder {
  double order;
  std::string source;
};
inline constexpr double kDonorCellFormalOrder = 1.0;  // first-order remap of the CEL rung
MeasuredOrder measured_hopper_rate_order();                       // of the shipped table
MeasuredOrder measured_hopper_rate_order(const MeasuredBench& table);

struct CalibrationDesign {
  std::string case_file;                 // the hopper case whose outlet and semi-angle are varied
  std::string material;                  // its material (set on the case when it names another)
  std::string against = "cel";           // "cel" | "dem"
  std::vector<DesignPoint> points;
  std::vector<double> cells_across = {3.0, 6.0};  // CEL levels: cells across the half outlet, each twice the last
  std::optional<double> order;           // two-level Richardson order; none: measured_hopper_rate_order()
  std::optional<double> time;            // [s] simulated time; none: the scene's own end

  // Throws InputError (naming the flag) for no points, fewer than two fitted points, CEL levels
  // that do not double, or fewer than 3 cells across at the coarsest.
  void check() const;
};

// The W x theta grid (fitted) plus the held-out points.
std::vector<DesignPoint> grid_points(const std::vector<double>& outlet_widths, const std::vector<double>& semi_angles,
                                     const std::vector<DesignPoint>& held_out);

// The point as a bench question: id "W60mm_theta30deg", the case with the point's outlet and
// semi-angle set, and the rung's runs (CEL levels with the cel_refinement role, or the DEM run as
// the reference). The question's reference (bench_table's tabulate) is the point's reference.
BenchQuestion design_point_question(const CalibrationDesign& design, const DesignPoint& point);

}  // namespace feedflow
