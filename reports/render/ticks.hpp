#pragma once
// Round tick values for a colour bar or a scale bar (1, 2 or 5 times a power of ten).
#include <string>
#include <vector>

namespace feedflow::render {

// The largest 1, 2 or 5 x 10^k not above `limit` (> 0).
double round_length_below(double limit);

// Ticks at multiples of a round step inside [lo, hi], about `target` of them (at least two when
// lo < hi); {lo} when lo == hi.
std::vector<double> round_ticks(double lo, double hi, int target = 5);

// A tick label with as many decimals as the step needs ("0.25", "12", "-3.5").
std::string tick_label(double value, double step);

}  // namespace feedflow::render
