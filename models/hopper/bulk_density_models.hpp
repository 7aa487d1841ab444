#pragma once
// The bulk-density models of the hopper (`--model hopper.bulk_density=NAME`): rho_b against
// the major stress, as the flow factor, critical outlet and discharge models read it.
#include <optional>
#include <string>

#include "models/core/model_table.hpp"
#include "models/hopper/flow_function.hpp"
#include "models/material/bulk_compressibility.hpp"
#include "models/material/material.hpp"

namespace feedflow {

struct HopperDensity {
  BulkDensity density;
  std::string model;  // for the report's assumptions
};

// `m` has [flow_properties]; `compressibility` is BulkCompressibility::of(m). Throws InputError
// naming --model when the row needs data the material lacks.
using HopperDensityEvaluate = HopperDensity (*)(const Material& m,
                                                const std::optional<BulkCompressibility>& compressibility);
using HopperDensityModel = ModelRow<HopperDensityEvaluate>;

// compressible (default), table, constant.
const ModelTable<HopperDensityModel>& hopper_density_models();

}  // namespace feedflow
