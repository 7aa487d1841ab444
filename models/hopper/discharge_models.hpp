#pragma once
// The discharge-rate models (`--model hopper.discharge=NAME`): the steady mass flow rate of the
// hopper's outlet, per metre of slot (wedge) or total (cone), before the air-drag correction.
// The rate's band spans the rows that say so, at the nominal material values. Each row names
// its free coefficients (Beverloo's C and k, a factor on a theory's rate) with their published
// values; `feedflow calibrate` fits them to a full rung and the material's [calibration] table
// carries them to the design check.
#include <map>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "models/core/model_table.hpp"
#include "models/hopper/discharge_rate.hpp"

namespace feedflow {

struct DischargeInputs {
  FlowGeometry geometry;
  double semi_angle;                  // theta [rad]
  double outlet_width;                // B [m]
  const JohansonDischarge& johanson;  // its rate, and rho_b at the outlet stress
  double median_size;                 // d50 [m]; 0 when the material has no size distribution
  double effective_friction_angle = 0.0;  // delta [rad]
  double wall_friction_angle = 0.0;       // phi_w [rad]
};

struct DischargeRate {
  double rate;        // kg/(s m) plane, kg/s conical
  std::string model;  // the model text of the mass_flow_rate estimate
};

// A free coefficient of a row: its name in the [calibration] table, its published value for
// plane (wedge) and conical flow, the range a fit may put it in, and what it is.
struct DischargeCoefficient {
  std::string_view name;  // "c", "k", "factor"
  double published_plane;
  double published_conical;
  double lowest, highest;  // physically meaningful values
  std::string_view meaning;
};

// Evaluates with `coefficients` in the row's order (its published values, or calibrated ones).
// Nothing where the model does not apply (Brown-Richards on a cone): the default row stands in.
using DischargeEvaluate = std::optional<DischargeRate> (*)(const DischargeInputs&,
                                                          std::span<const double> coefficients);

struct DischargeModel : ModelEntry {
  DischargeEvaluate evaluate;
  std::string_view legend;  // the model's curve in the rate-against-outlet chart
  bool spans_band;          // one of the alternatives the rate's band spans
  std::span<const DischargeCoefficient> coefficients;

  // The row at its published coefficients.
  std::optional<DischargeRate> published(const DischargeInputs& in) const;
};

// The row's published coefficients for the geometry.
std::vector<double> published_coefficients(const DischargeModel& row, FlowGeometry g);
// "C2 = 1.03, k = 1.5": the coefficients as a model text shows them.
std::string coefficients_text(const DischargeModel& row, std::span<const double> coefficients);

// Coefficients fitted to a full rung, by row name (values in the row's order), for hoppers of
// one geometry; `source` says what they were fitted to, for the model text and the report.
struct DischargeCalibration {
  FlowGeometry geometry = FlowGeometry::plane;
  std::map<std::string, std::vector<double>, std::less<>> coefficients;
  std::string source;  // "calibrated against L2 CEL-FEM (pilot_hopper, 2026-12-02, 8c1f2e0)"
  // The row that met the full rung best: the smallest max error on the points left out of the
  // fit, or the smallest rms error of the fit when none were left out; empty when the
  // calibration gives neither figure. `best_row_error` is that figure as written ("1.38 %").
  std::string best_row;
  std::string best_row_error;
  // Each row's measured error against the full rung, as a fraction: the larger of its fit rms
  // error and its held-out max error (rows without either figure are absent). A calibrated row's
  // rate band spans it (assess_hopper).
  std::map<std::string, double, std::less<>> row_error;
};

// The coefficients a row evaluates with: calibrated ones where `calibration` has the row for
// this geometry, else the published ones. `calibrated` (optional) says which.
std::vector<double> coefficients_for(const DischargeModel& row, FlowGeometry g,
                                     const std::optional<DischargeCalibration>& calibration,
                                     bool* calibrated = nullptr);

// The row's measured error against the full rung (DischargeCalibration::row_error) when it
// evaluates with calibrated coefficients for this geometry; nothing otherwise.
std::optional<double> calibrated_error(const DischargeModel& row, FlowGeometry g,
                                       const std::optional<DischargeCalibration>& calibration);

// johanson (default; a material's calibration may name a better row, DischargeCalibration::
// best_row), beverloo, brown, rose_tanaka.
const ModelTable<DischargeModel>& discharge_models();

}  // namespace feedflow
