#include "designer/calibrate/calibration_design.hpp"

#include <cmath>

#include "designer/bench/measured_bench.hpp"
#include "models/core/errors.hpp"
#include "models/units/angle.hpp"
#include "models/units/quantity_format.hpp"

namespace feedflow {

MeasuredOrder measured_hopper_rate_order() { return measured_hopper_rate_order(measured_bench()); }

MeasuredOrder measured_hopper_rate_order(const MeasuredBench& table) {
  const MeasuredQuestion* q = table.find("hopper_discharge_rate_60mm");
  if (!q || !q->reference)
    throw NotAvailable(
        "the bench table has no reference for the hopper's discharge rate; give --order");
  if (!q->order)
    return {kDonorCellFormalOrder,
            "(the donor-cell remap's formal order; feedflow bench observed no order on the "
            "pilot hopper at W = 60 mm, " +
                table.date + ")"};
  // An order above the scheme's is not carried to other geometries: the pilot hopper's three
  // levels may converge faster than a two-level estimate elsewhere can assume.
  if (*q->order > kDonorCellFormalOrder)
    return {kDonorCellFormalOrder, "(the donor-cell remap's formal order; feedflow bench measured " +
                                       format_number(*q->order, 3) + " on the pilot hopper at W = 60 mm, " +
                                       table.date + ")"};
  return {*q->order, "(measured by feedflow bench on the pilot hopper at W = 60 mm, " + table.date + ")"};
}

void CalibrationDesign::check() const {
  std::size_t fitted = 0;
  for (const auto& p : points) fitted += !p.held_out;
  if (fitted < 2)
    throw InputError("--outlet-widths", std::to_string(fitted) + " point(s)",
                     "a calibration needs at least two fitted design points (outlet widths x semi-angles)");
  if (against != "cel") return;
  if (cells_across.empty()) throw InputError("--cells-across", "", "expected at least one level, e.g. 3,6");
  if (cells_across.front() < kReferenceCellsAcross)
    throw InputError("--cells-across", format_number(cells_across.front(), 3),
                     "at least " + format_number(kReferenceCellsAcross, 2) +
                         " cells across the half outlet: a coarser CEL run cannot resolve the outlet (the "
                         "pilot hopper reads \"arched\" at 1.5 cells)");
  for (std::size_t k = 1; k < cells_across.size(); ++k)
    if (std::abs(cells_across[k] / cells_across[k - 1] - 2.0) > 1e-9)
      throw InputError("--cells-across", format_number(cells_across[k], 3),
                       "each level must put twice the cells of the last (Richardson needs one refinement ratio)");
  if (order && !(*order > 0.0 && *order <= 8.0))
    throw InputError("--order", format_number(*order, 3), "expected an order of convergence in (0, 8]");
}

std::vector<DesignPoint> grid_points(const std::vector<double>& widths, const std::vector<double>& angles,
                                     const std::vector<DesignPoint>& held_out) {
  std::vector<DesignPoint> out;
  for (double w : widths)
    for (double a : angles) out.push_back({w, a, false});
  for (auto p : held_out) {
    p.held_out = true;
    out.push_back(p);
  }
  return out;
}

BenchQuestion design_point_question(const CalibrationDesign& d, const DesignPoint& pt) {
  const std::string width = millimetres_setting(pt.outlet_width);
  std::string angle = format_number(in_degrees(pt.semi_angle), 6) + "deg";
  BenchQuestion q;
  q.id = file_name_friendly("W" + width + "_theta" + angle);
  q.title = "W = " + format_number(pt.outlet_width * 1e3, 4) + " mm, theta = " +
            format_number(in_degrees(pt.semi_angle), 4) + " deg" + (pt.held_out ? " (held out)" : "");
  q.case_file = d.case_file;
  q.sets = {"hopper.outlet_width=" + width, "hopper.semi_angle=" + angle};
  if (!d.material.empty()) q.sets.push_back("case.material=" + d.material);
  const double half_outlet = 0.5 * pt.outlet_width;
  if (d.against == "dem") {
    BenchPoint p;
    p.setting = "DEM at the case's resolution";
    p.rung = "L3";
    p.quantity = "mass_flow_rate";
    p.solver = Solver::dem;
    p.time = d.time;
    p.role = ReferenceRole::dem_reference;
    q.points.push_back(std::move(p));
    return q;
  }
  // The finest level is rounded to 0.01 mm and the coarser ones are exact multiples of it, so
  // the levels keep one refinement ratio in the invocation's text.
  const double finest = std::max(1e-5, std::round(half_outlet / d.cells_across.back() / 1e-5) * 1e-5);
  for (std::size_t k = 0; k < d.cells_across.size(); ++k) {
    const double h = finest * std::pow(2.0, static_cast<double>(d.cells_across.size() - 1 - k));
    BenchPoint p;
    p.setting = "CEL cells " + millimetres_setting(h);
    p.rung = "L2";
    p.quantity = "mass_flow_rate";
    p.solver = Solver::cel;
    p.sets = {"cel.cell_size=" + millimetres_setting(h)};
    p.time = d.time;
    p.cell_size = h;
    p.role = ReferenceRole::cel_refinement;
    p.resolution = format_number(half_outlet / h, 3) + " cells across the half outlet";
    q.points.push_back(std::move(p));
  }
  if (d.cells_across.size() == 2) {
    const MeasuredOrder measured = d.order ? MeasuredOrder{*d.order, "(--order)"} : measured_hopper_rate_order();
    q.two_level_order = measured.order;
    q.two_level_order_source = measured.source;
  }
  return q;
}

}  // namespace feedflow
