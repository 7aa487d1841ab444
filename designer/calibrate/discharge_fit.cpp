#include "designer/calibrate/discharge_fit.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>

#include "models/core/errors.hpp"
#include "models/numerics/least_squares.hpp"
#include "models/units/quantity_format.hpp"

namespace feedflow {
namespace {

double slot_length_of(const Hopper& h) { return h.is_wedge() ? *h.slot_length : 1.0; }

// The row's rate [kg/s] at the observation with the coefficients `c`, as the design check
// evaluates it at the nominal material values; none where the row does not apply.
std::optional<double> row_rate(const DischargeModel& row, std::span<const double> c, const Hopper& h,
                               HopperMaterial& m) {
  m.discharge_calibration->coefficients[std::string(row.name)] = std::vector<double>(c.begin(), c.end());
  HopperModels models;
  models.discharge = &row;
  const auto variant = material_variants(m, *h.wall_friction_angle).front();
  const HopperEvaluation e = evaluate_hopper(h, h.semi_angle, h.outlet_width, m, variant, models);
  if (e.rate_row != &row) return std::nullopt;
  return e.rate * slot_length_of(h);
}

FitErrors errors_of(const std::vector<double>& rates,
                    const std::vector<DischargeObservation>& obs) {
  std::vector<double> references;
  std::vector<bool> held_out;
  for (const auto& o : obs) {
    references.push_back(o.reference);
    held_out.push_back(o.held_out);
  }
  return fit_errors(rates, references, held_out);
}

// Least squares over the free coefficients, holding at its published value any the fit takes
// out of its physical range and fitting the rest again. Fills f.after, f.standard_errors, f.held.
void fit_free_coefficients(const DischargeModel& row, const std::vector<DischargeObservation>& obs,
                           const std::vector<std::size_t>& fitted, HopperMaterial& m, DischargeRowFit& f) {
  std::vector<double> weight;  // each fitted point's relative uncertainty
  for (std::size_t i : fitted) weight.push_back(std::max(kFloorUncertainty, obs[i].error_bar / obs[i].reference));
  std::vector<bool> free(f.before.size(), true);
  for (;;) {
    std::vector<std::size_t> index;  // the free coefficients' places in the row
    std::vector<double> start;
    for (std::size_t k = 0; k < free.size(); ++k)
      if (free[k]) {
        index.push_back(k);
        start.push_back(f.before[k]);
      }
    std::vector<double> c = f.before;
    const auto residuals = [&](std::span<const double> p, std::span<double> r) {
      for (std::size_t k = 0; k < index.size(); ++k) c[index[k]] = p[k];
      for (std::size_t k = 0; k < fitted.size(); ++k) {
        const auto& o = obs[fitted[k]];
        try {
          r[k] = (*row_rate(row, c, o.hopper, m) / o.reference - 1.0) / weight[k];
        } catch (const std::invalid_argument&) {  // outside the row's domain (W <= k d): far off
          r[k] = 1e3;
        }
      }
    };
    const LeastSquaresFit fit = least_squares(residuals, start, fitted.size());
    f.after = f.before;
    f.standard_errors.assign(f.before.size(), 0.0);
    for (std::size_t k = 0; k < index.size(); ++k) {
      f.after[index[k]] = fit.parameters[k];
      f.standard_errors[index[k]] = fit.standard_errors[k];
    }
    bool refit = false;
    for (std::size_t k : index) {
      const DischargeCoefficient& spec = row.coefficients[k];
      if (f.after[k] >= spec.lowest && f.after[k] <= spec.highest) continue;
      f.held.push_back(std::string(spec.name) + " held at " + format_number(f.before[k], 3) + ": the fit put it at " +
                       format_number(f.after[k], 3) + ", outside [" + format_number(spec.lowest, 3) + ", " +
                       format_number(spec.highest, 3) + "]");
      free[k] = false;
      refit = true;
    }
    if (!refit) return;
    if (std::none_of(free.begin(), free.end(), [](bool x) { return x; }))
      throw NumericalFailure("every coefficient left its physical range");
  }
}

DischargeRowFit fit_row(const DischargeModel& row, const std::vector<DischargeObservation>& obs, HopperMaterial m,
                        FlowGeometry g) {
  DischargeRowFit f;
  f.row = &row;
  f.before = published_coefficients(row, g);
  DischargeCalibration trial_coefficients;
  trial_coefficients.geometry = g;
  trial_coefficients.source = "the fit's trial";
  m.discharge_calibration = std::move(trial_coefficients);
  for (const auto& o : obs) f.rate_before.push_back(*row_rate(row, f.before, o.hopper, m));
  std::vector<std::size_t> fitted;
  for (std::size_t i = 0; i < obs.size(); ++i)
    if (!obs[i].held_out) fitted.push_back(i);
  try {
    if (fitted.size() < row.coefficients.size())
      throw std::invalid_argument("fewer fitted points than coefficients");
    fit_free_coefficients(row, obs, fitted, m, f);
    for (const auto& o : obs) f.rate_after.push_back(*row_rate(row, f.after, o.hopper, m));
  } catch (const std::exception& e) {
    f.failure = e.what();
    f.after = f.before;
    f.standard_errors.assign(f.before.size(), 0.0);
    f.rate_after = f.rate_before;
  }
  const FitErrors before = errors_of(f.rate_before, obs), after = errors_of(f.rate_after, obs);
  f.fit_rms_before = before.fit_rms;
  f.held_out_max_before = before.held_out_max;
  f.fit_rms_after = after.fit_rms;
  f.held_out_max_after = after.held_out_max;
  return f;
}

// The design check's q_m and whether its band holds the reference, for each observation.
void design_figures(const std::vector<DischargeObservation>& obs, const HopperMaterial& m, const HopperModels& models,
                    std::vector<double>& rate, std::vector<bool>& holds) {
  for (const auto& o : obs) {
    const HopperAssessment a = assess_hopper(o.hopper, m, models);
    const double length = slot_length_of(o.hopper);
    rate.push_back(a.nominal().rate * length);
    const Band band = a.rate.scaled(length);
    holds.push_back(band.low <= o.reference && o.reference <= band.high);
  }
}

}  // namespace

double relative_error(double a, double b) { return std::abs(a / b - 1.0); }

std::string percent(double relative) { return format_number(100.0 * relative, 3) + " %"; }

FitErrors fit_errors(const std::vector<double>& values, const std::vector<double>& references,
                     const std::vector<bool>& held_out) {
  FitErrors e;
  std::size_t n = 0;
  for (std::size_t i = 0; i < values.size(); ++i) {
    const double err = relative_error(values[i], references[i]);
    if (held_out[i])
      e.held_out_max = std::max(e.held_out_max, err);
    else {
      e.fit_rms += err * err;
      ++n;
    }
  }
  e.fit_rms = n ? std::sqrt(e.fit_rms / static_cast<double>(n)) : 0.0;
  return e;
}

DischargeFit fit_discharge(const std::vector<DischargeObservation>& obs, HopperMaterial m, const HopperModels& models) {
  if (std::none_of(obs.begin(), obs.end(), [](const DischargeObservation& o) { return !o.held_out; }))
    throw std::invalid_argument("a discharge fit needs observations to fit");
  const FlowGeometry g = flow_geometry(obs.front().hopper);
  for (const auto& o : obs)
    if (flow_geometry(o.hopper) != g) throw std::invalid_argument("a discharge fit takes hoppers of one geometry");
  m.discharge_calibration.reset();
  m.calibration_note.clear();
  DischargeFit out;
  out.calibration.geometry = g;
  for (const DischargeModel& row : discharge_models().rows) {
    // A row that does not apply to the geometry (Brown-Richards on a cone) has nothing to fit.
    HopperMaterial trial = m;
    trial.discharge_calibration = DischargeCalibration{};
    trial.discharge_calibration->geometry = g;
    if (!row_rate(row, published_coefficients(row, g), obs.front().hopper, trial)) continue;
    DischargeRowFit f = fit_row(row, obs, m, g);
    if (f.failure.empty()) out.calibration.coefficients.emplace(std::string(row.name), f.after);
    out.rows.push_back(std::move(f));
  }
  design_figures(obs, m, models, out.design_before, out.band_holds_before);
  HopperMaterial calibrated = m;
  calibrated.discharge_calibration = out.calibration;
  design_figures(obs, calibrated, models, out.design_after, out.band_holds_after);
  return out;
}

void set_error_figures(CalibratedModel& m, const FitErrors& before, const FitErrors& after,
                       bool held_out) {
  m.figures["fit_rms_error_before"] = percent(before.fit_rms);
  m.figures["fit_rms_error"] = percent(after.fit_rms);
  if (!held_out) return;
  m.figures["held_out_max_error_before"] = percent(before.held_out_max);
  m.figures["held_out_max_error"] = percent(after.held_out_max);
}

}  // namespace feedflow
