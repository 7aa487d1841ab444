#pragma once
// A run's time series as CSV: one header line "time [s],discharged_mass [kg],...", then one
// line per sample with 17 significant digits (a reader gets the doubles back exactly).
#include <string>

#include "models/core/time_series.hpp"

namespace feedflow {

std::string to_csv(const TimeSeries& series);

}  // namespace feedflow
