#pragma once
// The judges: one per equipment, from the case's equipment and [design] targets and a list of
// estimates of ANY rung (the reduced models' or a simulation's results) to a verdict. A judge
// reads only the quantities present and says nothing of those absent, so every rung is judged
// by the same rules. Each reason is a Finding with the quantity's key and numbers, and states
// the rule applied.
//
// Quantities read (a missing one is not judged):
// - hopper: flow_pattern ("mass"/"funnel"), mass_flow_limit_angle, flow_pattern_margin,
//   flow_pattern_boundary; arching (reduced: "cohesive arch below B_c", "no cohesive arch",
//   "no gravity outlet"; simulated: "arched", "flowing", "flows", "emptied (no arch)"),
//   critical_outlet_width (against outlet_safety_factor), mechanical_arching_width;
//   mass_flow_rate (against required_throughput).
// - chute: deposit (reduced label), stopping_thickness and deposit_thickness_mid_ramp (against
//   max_stopping_thickness).
// - drum: regime (a regime's name, or "not measured"), froude_number, regime_boundary_ratio;
//   full_bed_centrifuging_speed; no_slip_wall_friction.
#include "designer/case/case.hpp"
#include "models/core/design_record.hpp"

namespace feedflow {

Verdict judge_hopper(const Hopper& hopper, const DesignTargets& targets, const Estimates& estimates);
Verdict judge_chute(const Chute& chute, const DesignTargets& targets, const Estimates& estimates);
Verdict judge_drum(const Drum& drum, const DesignTargets& targets, const Estimates& estimates);

// The judge of the case's equipment.
Verdict judge(const Case& c, const Estimates& estimates);

}  // namespace feedflow
