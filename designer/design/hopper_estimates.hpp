#pragma once
// The hopper check's evaluate step: every chosen model at every corner of the material's
// uncertainty box, and the model alternatives at the nominal values, turned into the record's
// estimates with their bands (flow pattern and its margin, flow factor, arching and B_c,
// interlocking, discharge, content and emptying time).
#include <optional>
#include <vector>

#include "designer/case/case.hpp"
#include "models/core/band.hpp"
#include "models/core/design_record.hpp"
#include "models/hopper/critical_outlet.hpp"
#include "models/hopper/flow_pattern.hpp"
#include "models/hopper/hopper_evaluation.hpp"

namespace feedflow {

// The uncertainty box evaluated.
struct HopperAssessment {
  HopperMaterial material;
  HopperModels models;
  FlowPatternVerdict pattern;                 // at the nominal values
  Band limit;                                 // mass-flow limit over the box and its rule's band [rad]
  std::vector<HopperEvaluation> evaluations;  // the nominal values first, then the corners
  Band flow_factor, width, jenike, static_arch;
  Band rate;                                  // over the box and the discharge alternatives, per metre or total
  std::optional<MechanicalArching> mechanical;

  const HopperEvaluation& nominal() const { return evaluations.front(); }
};

HopperAssessment assess_hopper(const Hopper& h, HopperMaterial m, const HopperModels& models);

// The record's estimates, and what the models said in words (notes, each on its quantity).
struct HopperEstimates {
  Estimates results;
  std::vector<Finding> notes;
};

HopperEstimates hopper_estimates(const Material& material, const Hopper& h, const HopperAssessment& a);

}  // namespace feedflow
