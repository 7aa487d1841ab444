#include "models/hopper/flow_factor_models.hpp"

#include "models/hopper/enstad_flow_factor.hpp"
#include "models/hopper/radial_stress_field.hpp"

namespace feedflow {
namespace {

double radial_field(FlowGeometry g, double theta, double delta, double phi_w) {
  const auto field = solve_radial_stress_field(g, theta, delta, phi_w);
  // Beyond the existence limit there is no radial field (funnel flow): Enstad's closed form
  // still gives the arching estimate.
  return field ? field->flow_factor : enstad_flow_factor(g, theta, delta, phi_w);
}

constexpr FlowFactorModel kFlowFactorRows[] = {
    {{"enstad", Rung::L0, "Enstad/Arnold-McLean closed form"}, &enstad_flow_factor},
    {{"rsf", Rung::L1, "Jenike radial stress field (shooting)"}, &radial_field},
};

constexpr ModelTable<FlowFactorModel> kFlowFactorTable{"hopper.flow_factor", "flow factor",
                                                       kFlowFactorRows};

}  // namespace

const ModelTable<FlowFactorModel>& flow_factor_models() { return kFlowFactorTable; }

}  // namespace feedflow
