#pragma once
// What the hopper models take from a material, and the box of its uncertainty: the nominal
// values and the corners of delta, phi_w and the flow function's strength, each at -, 0, + its
// uncertainty. The design check evaluates the hopper at every corner; the charts sweep them.
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "models/hopper/bulk_density_models.hpp"
#include "models/hopper/discharge_models.hpp"
#include "models/hopper/flow_function.hpp"
#include "models/material/material.hpp"

namespace feedflow {

// The flow function's strength scale in the arching models, fitted to a full rung's critical
// outlet widths for hoppers of one geometry with one flow-factor row, by hopper.critical_outlet
// row; `source` says what it was fitted to, for the model text.
struct ArchingScale {
  FlowGeometry geometry = FlowGeometry::plane;
  std::string flow_factor;
  std::map<std::string, double, std::less<>> strength_scale;
  std::string source;  // "sigma_c x 1.21, calibrated against L3 DEM (pilot_hopper, 2026-12-07)"
};

struct HopperMaterial {
  FlowProperties flow;
  BulkDensity density = BulkDensity::constant(1.0);
  std::string density_model;                 // for the report
  std::optional<double> median_size;         // d50 [m]
  std::optional<double> largest_size;        // d90, taken as d_max [m]
  std::optional<double> particle_density;    // envelope density, for the air-drag correction
  // The material's calibrated discharge coefficients, when they were fitted with this density
  // model; `calibration_note` says why a [calibration] is not used otherwise.
  std::optional<DischargeCalibration> discharge_calibration;
  std::string calibration_note;
  std::optional<ArchingScale> arching_calibration;

  // Throws InputError when the material lacks the [flow_properties] section.
  static HopperMaterial of(const Material& m,
                           const HopperDensityModel& density = hopper_density_models().default_row());
};

// One corner of the uncertainty box.
struct MaterialVariant {
  double effective_friction_angle;  // delta [rad]
  double wall_friction_angle;       // phi_w [rad]
  double strength_scale;            // multiplies sigma_c
};

// The nominal variant first, then the corners (each value at -, 0, + its uncertainty; only the
// 8 corners with every value off its nominal when corners_only).
std::vector<MaterialVariant> material_variants(const HopperMaterial& m, double wall_friction_angle,
                                               bool corners_only = false);

// The calibrated strength scale of the arching row `critical_outlet` for this geometry and
// flow-factor row (1 without a calibration that applies); `calibrated` (optional) says which.
double arching_strength_scale(const HopperMaterial& m, FlowGeometry g, std::string_view flow_factor,
                              std::string_view critical_outlet, bool* calibrated = nullptr);

// The material's flow function with sigma_c scaled by `scale`.
FlowFunction scaled_flow_function(const FlowProperties& p, double scale);

}  // namespace feedflow
