#pragma once
// The hopper models evaluated for one set of material values (one corner of the uncertainty
// box) with the chosen rows of the model tables: flow factor, critical outlet widths and
// discharge.
#include <optional>
#include <string>

#include "models/equipment/hopper.hpp"
#include "models/hopper/critical_outlet.hpp"
#include "models/hopper/critical_outlet_models.hpp"
#include "models/hopper/discharge_models.hpp"
#include "models/hopper/flow_factor_models.hpp"
#include "models/hopper/hopper_material.hpp"

namespace feedflow {

// The chosen row of each hopper model table (the bulk density is chosen with the material).
struct HopperModels {
  const FlowFactorModel* flow_factor = &flow_factor_models().default_row();
  const CriticalOutletModel* critical_outlet = &critical_outlet_models().default_row();
  const DischargeModel* discharge = &discharge_models().default_row();
};

struct HopperEvaluation {
  double flow_factor = 0.0;
  CriticalOutlet jenike;
  std::optional<CriticalOutlet> static_arch;  // plane hoppers only
  double critical_width = 0.0;                 // by the chosen critical-outlet model [m]
  std::string critical_model;
  JohansonDischarge johanson;
  double rate = 0.0;        // chosen discharge model, per metre (wedge) or total (cone), with air drag
  double drag_factor = 1.0;
  std::string rate_model;
  const DischargeModel* rate_row = nullptr;  // the row that gave the rate (the default where the chosen one does not apply)
};

HopperEvaluation evaluate_hopper(const Hopper& h, double semi_angle, double outlet_width,
                                 const HopperMaterial& m, const MaterialVariant& v,
                                 const HopperModels& models = {});

}  // namespace feedflow
