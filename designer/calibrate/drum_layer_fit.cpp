#include "designer/calibrate/drum_layer_fit.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "designer/calibrate/discharge_fit.hpp"
#include "designer/design/drum_check.hpp"
#include "models/core/errors.hpp"
#include "models/numerics/least_squares.hpp"
#include "models/units/angle.hpp"
#include "models/units/quantity_format.hpp"

namespace feedflow {
namespace {

// The material with (c_delta, shift) as its drum calibration, without figures (no widening).
void set_trial(Material& m, double layer_fraction, double shift) {
  DrumCalibration& c = m.calibration->drum.emplace();
  c.layer.coefficients = {{"layer_fraction", layer_fraction}, {"friction_shift", shift}};
}

FitErrors errors_of(const std::vector<double>& angles, const std::vector<DrumObservation>& obs) {
  std::vector<double> references;
  std::vector<bool> held_out;
  for (const auto& o : obs) {
    references.push_back(o.reference);
    held_out.push_back(o.held_out);
  }
  return fit_errors(angles, references, held_out);
}

// The design check's nominal angle and whether its band holds the reference, per observation.
void design_figures(const std::vector<DrumObservation>& obs, const Material& m,
                    std::vector<double>& angle, std::vector<bool>& holds) {
  angle.clear();
  holds.clear();
  for (const auto& o : obs) {
    const AngleOfRepose a = rolling_angle_band(o.drum, m);
    angle.push_back(a.nominal);
    holds.push_back(a.low <= o.reference && o.reference <= a.high);
  }
}

// Least squares over c_delta (unless held) and the shift [deg in the solver]; fills f's after
// values.
void fit_coefficients(const std::vector<DrumObservation>& obs, Material& m, DrumLayerFit& f) {
  std::vector<std::size_t> fitted;
  std::vector<double> weight;
  for (std::size_t i = 0; i < obs.size(); ++i)
    if (!obs[i].held_out) {
      fitted.push_back(i);
      weight.push_back(std::max(kFloorUncertainty, obs[i].error_bar / obs[i].reference));
    }
  for (bool hold_fraction : {false, true}) {
    const auto residuals = [&](std::span<const double> p, std::span<double> r) {
      const double fraction = hold_fraction ? f.layer_fraction_before : p[0];
      const double shift = p[hold_fraction ? 0 : 1] * kDegree;
      set_trial(m, fraction, shift);
      for (std::size_t k = 0; k < fitted.size(); ++k) {
        const auto& o = obs[fitted[k]];
        try {
          r[k] = (rolling_angle_band(o.drum, m).nominal / o.reference - 1.0) / weight[k];
        } catch (const std::exception&) {  // outside the layer's domain: far off
          r[k] = 1e3;
        }
      }
    };
    std::vector<double> start = {f.shift_before / kDegree};
    if (!hold_fraction) start.insert(start.begin(), f.layer_fraction_before);
    const LeastSquaresFit fit = least_squares(residuals, start, fitted.size());
    if (!hold_fraction) {
      const double fraction = fit.parameters[0];
      if (fraction < kLayerFractionLowest || fraction > kLayerFractionHighest) {
        f.held = "c_delta held at " + format_number(f.layer_fraction_before, 3) +
                 ": the fit put it at " + format_number(fraction, 3) + ", outside [" +
                 format_number(kLayerFractionLowest, 3) + ", " +
                 format_number(kLayerFractionHighest, 3) + "]";
        continue;
      }
      f.layer_fraction_after = fraction;
      f.layer_fraction_error = fit.standard_errors[0];
    } else {
      f.layer_fraction_after = f.layer_fraction_before;
    }
    f.shift_after = fit.parameters.back() * kDegree;
    f.shift_error = fit.standard_errors.back() * kDegree;
    if (!(std::abs(f.shift_after) <= 30.0 * kDegree))
      throw NumericalFailure("the friction shift left +-30 deg (" +
                             format_quantity(f.shift_after, "deg", 3) + ")");
    return;
  }
}

}  // namespace

DrumLayerFit fit_drum_layer(const std::vector<DrumObservation>& obs, Material m, bool end_walls) {
  if (std::none_of(obs.begin(), obs.end(), [](const DrumObservation& o) { return !o.held_out; }))
    throw std::invalid_argument("a drum layer fit needs observations to fit");
  if (!m.drum_flow || !m.surface_flow)
    throw std::invalid_argument(
        "a drum layer fit needs the material's [drum_flow] and [surface_flow]");
  if (!end_walls) m.drum_flow->end_wall_friction = 0.0;  // the rung's slice has none
  if (!m.calibration) m.calibration.emplace();
  m.calibration->drum.reset();
  DrumLayerFit f;
  f.layer_fraction_before = m.drum_flow->layer_fraction;
  design_figures(obs, m, f.angle_before, f.band_holds_before);
  try {
    Material trial = m;
    fit_coefficients(obs, trial, f);
  } catch (const std::exception& e) {
    f.failure = e.what();
    f.layer_fraction_after = f.layer_fraction_before;
    f.shift_after = 0.0;
  }
  const FitErrors before = errors_of(f.angle_before, obs);
  f.fit_rms_before = before.fit_rms;
  f.held_out_max_before = before.held_out_max;
  Material calibrated = m;
  set_trial(calibrated, f.layer_fraction_after, f.shift_after);
  std::vector<bool> unused;
  design_figures(obs, calibrated, f.angle_after, unused);
  const FitErrors after = errors_of(f.angle_after, obs);
  f.fit_rms_after = after.fit_rms;
  f.held_out_max_after = after.held_out_max;

  f.layer.coefficients = {{"layer_fraction", f.layer_fraction_after},
                          {"friction_shift", f.shift_after}};
  set_error_figures(
      f.layer, before, after,
      std::any_of(obs.begin(), obs.end(), [](const DrumObservation& o) { return o.held_out; }));
  if (!f.held.empty()) f.layer.figures["held_1"] = f.held;
  // The band after: the design check's with the calibration's figures (widened by its error).
  calibrated.calibration->drum->layer = f.layer;
  design_figures(obs, calibrated, f.angle_after, f.band_holds_after);
  return f;
}

}  // namespace feedflow
