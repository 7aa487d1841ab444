#pragma once
// The hopper design check: evaluate (hopper_estimates: the models over the material's
// uncertainty and the model alternatives), judge (judge_hopper: flow pattern, arching,
// interlocking, throughput against the case's [design] targets) and explain (what the models
// assume and which way each errs; the charts).
#include "designer/case/case.hpp"
#include "designer/design/design_detail.hpp"
#include "designer/design/hopper_estimates.hpp"
#include "designer/design/model_choices.hpp"
#include "models/core/design_record.hpp"

namespace feedflow {

// The chosen rows of the hopper's model tables. Where --model leaves hopper.discharge unset and
// the material carries discharge coefficients calibrated for this hopper's geometry, the rate is
// the calibrated row that met the full rung best (DischargeCalibration::best_row).
HopperModels hopper_models(const ModelChoices& choices, const HopperMaterial& material, const Hopper& h);

// Fills the record's results, verdict, charts and assumptions.
void check_hopper(const Case& c, const Hopper& hopper, const ModelChoices& models,
                  DesignDetail detail, DesignRecord& record);

// What the hopper models assume, and which way each number errs; `rate_row_from_calibration`:
// the rate's row is the calibration's best, not one --model chose.
std::vector<std::string> hopper_assumptions(const Case& c, const Hopper& h, const HopperAssessment& a,
                                            bool rate_row_from_calibration);

}  // namespace feedflow
