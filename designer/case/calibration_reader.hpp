#pragma once
// Reads a material's [calibration] table (written by `feedflow calibrate`): what it was fitted
// to, and per hopper.discharge row its coefficients (names checked against the row) and figures.
#include <string>
#include <toml++/toml.h>

#include "designer/case/table_reader.hpp"
#include "models/material/calibration.hpp"

namespace feedflow {

// `ctx.prefix` is the table's dotted path ("calibration", "material.calibration").
Calibration read_calibration(const toml::table& table, const TableContext& ctx);

}  // namespace feedflow
