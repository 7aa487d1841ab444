#pragma once
// Test support: the rate of a CEL run's outflow ledger as a plain least-squares slope (the
// CEL scene tests' own yardstick of the solver's discharge; the designer measures every rung's
// discharge with fullsim/common/discharge_measurement.hpp).
#include <algorithm>
#include <cstddef>
#include <vector>

#include "fullsim/cel/discharge_ledger.hpp"

namespace feedflow::cel {

struct DischargeRate {
  double rate = 0.0;          // least-squares slope over the window [kg/s per m depth]
  double low = 0.0, high = 0.0;  // smallest and largest slope of the window's four quarters
  double window_start = 0.0, window_end = 0.0;  // [s]
  double final_rate = 0.0;    // slope over the last quarter of the run [kg/s/m]
};

// The rate over the steady window: from `start` to the end of the ledger, ended early when the
// grid holds less than 20 % of `initial_mass` (the hopper is running empty); defined below.
namespace ledger_rate_detail {
// Least-squares slope of y(x) over the samples [first, last).
inline double slope(const std::vector<DischargeSample>& s, std::size_t first, std::size_t last) {
  if (last <= first + 1) return 0.0;
  double mx = 0.0, my = 0.0;
  const double n = static_cast<double>(last - first);
  for (std::size_t k = first; k < last; ++k) mx += s[k].time, my += s[k].mass;
  mx /= n, my /= n;
  double sxy = 0.0, sxx = 0.0;
  for (std::size_t k = first; k < last; ++k) {
    sxy += (s[k].time - mx) * (s[k].mass - my);
    sxx += (s[k].time - mx) * (s[k].time - mx);
  }
  return sxx > 0.0 ? sxy / sxx : 0.0;
}

}  // namespace ledger_rate_detail

inline DischargeRate discharge_rate(const DischargeLedger& ledger, double start, double initial_mass) {
  using ledger_rate_detail::slope;
  const auto& h = ledger.history();
  DischargeRate r;
  std::size_t first = 0;
  while (first < h.size() && h[first].time < start) ++first;
  std::size_t last = first;
  while (last < h.size() && initial_mass - h[last].mass > 0.2 * initial_mass) ++last;
  if (last <= first + 4) return r;
  r.window_start = h[first].time;
  r.window_end = h[last - 1].time;
  r.rate = slope(h, first, last);
  r.low = r.high = r.rate;
  const std::size_t q = (last - first) / 4;
  for (int k = 0; k < 4; ++k) {
    const double s = slope(h, first + k * q, first + (k + 1) * q);
    r.low = std::min(r.low, s);
    r.high = std::max(r.high, s);
  }
  const std::size_t tail = h.size() - std::max<std::size_t>((h.size() - first) / 4, 2);
  r.final_rate = slope(h, std::max(tail, first), h.size());
  return r;
}

}  // namespace feedflow::cel
