#pragma once
// The critical-outlet models (`--model hopper.critical_outlet=NAME`): which cohesive-arching
// estimate gives the hopper's critical outlet width B_c, from Jenike's and (plane hoppers) the
// static-arch estimate.
#include <optional>
#include <string>

#include "models/core/model_table.hpp"
#include "models/hopper/critical_outlet.hpp"

namespace feedflow {

struct CriticalWidth {
  double width;       // B_c [m]
  std::string model;  // the model text of the critical_outlet_width estimate
};

using CriticalWidthEvaluate = CriticalWidth (*)(const CriticalOutlet& jenike,
                                                const std::optional<CriticalOutlet>& static_arch);
using CriticalOutletModel = ModelRow<CriticalWidthEvaluate>;

// envelope (default), jenike, static_arch.
const ModelTable<CriticalOutletModel>& critical_outlet_models();

}  // namespace feedflow
