#pragma once
// Richardson extrapolation of a quantity computed at three resolutions (cell sizes h1 > h2 > h3
// with one refinement ratio r = h1/h2 = h2/h3): the observed order of convergence
// p = ln((f2 - f1) / (f3 - f2)) / ln r, the extrapolated value f3 + (f3 - f2) / (r^p - 1) and
// its error bar, Roache's grid convergence index with the safety factor 1.25 (Celik et al.
// 2008, J. Fluids Eng. 130, 078001). Converging without monotone differences (the differences
// change sign or one is zero) has no observed order: the estimate is then the finest value with
// the largest difference of the three as its error bar, flagged as outside the asymptotic range.
//
//   const RichardsonEstimate e = richardson({0.02, 0.01, 0.005}, {6.9, 6.21, 5.75});
//   e.value; e.error_bar; e.order;
#include <array>
#include <optional>

namespace feedflow {

struct RichardsonEstimate {
  double value = 0.0;            // the extrapolated value (or the finest, see `asymptotic`)
  double error_bar = 0.0;        // >= 0, in the value's unit
  std::optional<double> order;   // observed order; none when the differences are not monotone
  bool asymptotic = false;       // an order was observed (0.5 <= p <= 8 is plausible)
  bool diverging = false;        // no order: the differences keep their sign and grow
};

// `h`: the resolutions, coarse to fine, with one ratio (to 1e-6); `f`: the values. Throws
// std::invalid_argument for resolutions that do not shrink by one ratio or non-finite values.
RichardsonEstimate richardson(const std::array<double, 3>& h, const std::array<double, 3>& f);

// Two resolutions and a formal order (none observed): Roache's two-grid estimate, safety 3.
RichardsonEstimate richardson_two_levels(const std::array<double, 2>& h, const std::array<double, 2>& f,
                                         double formal_order);

}  // namespace feedflow
