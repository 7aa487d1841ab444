#pragma once
// Fits the drum's flowing layer (c_delta and a friction shift of theta1 and theta2, drum_check)
// to full-rung angles of repose over drum speeds by least squares on the relative error, each
// point weighted by its reference's relative uncertainty (at least kFloorUncertainty), through
// the design check's own evaluation (rolling_angle_band with the trial as the material's
// [calibration.drum]), and measures the design check before and after on the fitted and the
// held-out speeds. A c_delta the fit takes out of its physical range is held at the material's
// and the shift alone is fitted: a layer thicker than half the chord is no flowing layer.
#include <string>
#include <vector>

#include "models/equipment/drum.hpp"
#include "models/material/material.hpp"

namespace feedflow {

// c_delta's physical range (reduced_models.md section 4 gives 0.1-0.3 as observed).
inline constexpr double kLayerFractionLowest = 0.05;
inline constexpr double kLayerFractionHighest = 0.5;

// One design point: the drum at its speed and the full rung's angle of repose there.
struct DrumObservation {
  Drum drum;
  double reference = 0.0;  // [rad]
  double error_bar = 0.0;  // [rad]
  bool held_out = false;
};

struct DrumLayerFit {
  double layer_fraction_before = 0.0, layer_fraction_after = 0.0;
  double shift_before = 0.0, shift_after = 0.0;                // [rad]
  double layer_fraction_error = 0.0, shift_error = 0.0;        // standard errors (0: held)
  std::string held;                                            // c_delta held, and why
  std::vector<double> angle_before, angle_after;               // the design check's nominal [rad]
  std::vector<bool> band_holds_before, band_holds_after;       // its band holds the reference
  double fit_rms_before = 0.0, fit_rms_after = 0.0;            // relative error, fitted points
  double held_out_max_before = 0.0, held_out_max_after = 0.0;  // largest relative error, held out
  std::string failure;    // why the layer kept its published values
  CalibratedModel layer;  // coefficients and figures, for the material
};

// `material`: the published material (its own drum calibration ignored); `end_walls`: whether the
// rung's drum had end walls (a CEL slice has none: the fit then takes the material's end-wall
// friction as 0). Throws std::invalid_argument without fitted observations.
DrumLayerFit fit_drum_layer(const std::vector<DrumObservation>& observations, Material material,
                            bool end_walls);

}  // namespace feedflow
