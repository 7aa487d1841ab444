#pragma once
// How a judge reads a list of estimates of any rung: the numbers and labels present, their
// values in the unit people read, and a finding that carries the quantity's key and numbers.
#include <optional>
#include <string>
#include <string_view>

#include "models/core/design_record.hpp"

namespace feedflow {

// The estimate of `key` when it is a number; null when absent or a label.
const Estimate* number_of(const Estimates& estimates, std::string_view key);
// The label of `key`; empty when absent or a number.
std::optional<std::string> label_of(const Estimates& estimates, std::string_view key);

// A value of `e` (in e.unit) as people read it, in e's display unit, 3 significant digits:
// "30.6 mm", "49.6 deg", "2.84 kg/s".
std::string shown(const Estimate& e, double value);
std::string shown(const Estimate& e);  // its own value
// "20.5 mm .. 42.2 mm", or "" without a band.
std::string band_of(const Estimate& e);
// "30.6 mm (band 20.5 mm .. 42.2 mm)", or shown(e) without a band.
std::string shown_with_band(const Estimate& e);

// A finding on `key` with the estimate's value, band and unit (none when `e` is null) and the
// limit (in e.unit) it was judged against.
Finding finding(std::optional<VerdictStatus> status, std::string key, std::string text, const Estimate* e = nullptr,
                std::optional<double> limit = std::nullopt);

}  // namespace feedflow
