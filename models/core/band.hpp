#pragma once
// The range a value takes over an uncertainty box or a set of model alternatives, and the
// estimates built from it.
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "models/core/estimate.hpp"

namespace feedflow {

struct Band {
  double low = std::numeric_limits<double>::infinity();
  double high = -std::numeric_limits<double>::infinity();

  // Widens the band to `v`; values that are not finite (no arch, no outlet) are left out.
  void add(double v) {
    if (!std::isfinite(v)) return;
    low = std::min(low, v);
    high = std::max(high, v);
  }
  bool empty() const { return !(low <= high); }
  Band scaled(double factor) const { return {low * factor, high * factor}; }
};

// A number whose band is `band` widened to contain the value; no band when `band` is empty.
inline Estimate banded(double value, std::string unit, const Band& band, std::string model, Rung rung,
                       std::string display_unit = "") {
  Estimate e{value, std::move(unit), std::nullopt, std::nullopt, std::move(model), rung, std::move(display_unit)};
  if (!band.empty()) {
    e.low = std::min(band.low, value);
    e.high = std::max(band.high, value);
  }
  return e;
}

// A number without a band.
inline Estimate unbanded(double value, std::string unit, std::string model, Rung rung) {
  return Estimate{value, std::move(unit), std::nullopt, std::nullopt, std::move(model), rung, ""};
}

// A label ("mass", "rolling").
inline Estimate labelled(std::string value, std::string model, Rung rung = Rung::L0) {
  return Estimate{std::move(value), "", std::nullopt, std::nullopt, std::move(model), rung, ""};
}

}  // namespace feedflow
