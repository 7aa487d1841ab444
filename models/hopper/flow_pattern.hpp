#pragma once
// Mass flow or funnel flow (reduced_models.md section 1.6). Conical: the Arnold-McLean fit to
// Jenike's boundary. Wedge: no verified closed form exists, so the interim rule
// theta_c(conical) + 8...12 deg, labelled as such. Both with a 3 deg design margin and the
// "ff > 1.5 min ff" near-the-boundary criterion.
#include <numbers>
#include <string>

#include "models/hopper/hopper_geometry.hpp"

namespace feedflow {

enum class FlowPattern { mass, funnel };
const char* to_string(FlowPattern p);

inline constexpr double kDesignAngleMargin = 3.0 * std::numbers::pi / 180.0;

// Arnold-McLean: theta_c = 90 deg - 1/2 acos[(1 - sin delta)/(2 sin delta)] - beta [rad].
// Throws std::invalid_argument when the formula has no boundary (delta < 19.47 deg).
double conical_mass_flow_limit(double effective_friction_angle, double wall_friction_angle);

// Largest semi-angle for mass flow, with the band of the rule that gives it [rad].
struct MassFlowLimit {
  double nominal;
  double low;
  double high;
  std::string model;
};
// Wedge interim rule: theta_c(conical) + 10 deg, band + 8...12 deg.
MassFlowLimit wedge_mass_flow_limit(double effective_friction_angle, double wall_friction_angle);
MassFlowLimit mass_flow_limit(FlowGeometry g, double effective_friction_angle,
                              double wall_friction_angle);

struct FlowPatternVerdict {
  FlowPattern pattern;         // mass when theta <= the nominal limit
  MassFlowLimit limit;         // the boundary used, with its model name
  double margin;               // nominal limit - theta [rad]; negative in funnel flow
  double flow_factor_ratio;    // ff(theta) / min over (0, limit] of ff (Enstad); 0 in funnel flow
  bool near_boundary;          // within the design margin of the band's low end, or ratio > 1.5
                               // on the flat-wall side of the ff minimum
  std::string reason;          // in words, for the report
};

// The labels of the flow_pattern_boundary estimate (FlowPatternVerdict::near_boundary).
inline constexpr const char* kNearBoundary = "near the boundary";
inline constexpr const char* kClearOfBoundary = "clear of the boundary";

// Classifies a hopper of semi-angle theta; design_margin is the standard 3 deg.
FlowPatternVerdict classify_flow_pattern(FlowGeometry g, double semi_angle,
                                         double effective_friction_angle,
                                         double wall_friction_angle,
                                         double design_margin = kDesignAngleMargin);

}  // namespace feedflow
