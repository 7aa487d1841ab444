#include "designer/calibrate/stop_law_fit.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <optional>
#include <stdexcept>

#include "designer/calibrate/discharge_fit.hpp"
#include "designer/design/chute_check.hpp"
#include "models/chute/stopping_thickness_models.hpp"
#include "models/numerics/least_squares.hpp"
#include "models/units/angle.hpp"
#include "models/units/quantity_format.hpp"

namespace feedflow {
namespace {

// A theta2 the fit may not pass: a law that needs it has no stopping angle worth the name.
constexpr double kSteepestTheta2 = 89.0 * kDegree;

// The law's coefficients: theta2 and L, and theta1 when the fit frees it (else null).
std::map<std::string, double> coefficients_of(double theta2, double length, const double* theta1) {
  std::map<std::string, double> c{{"theta2", theta2}, {"stop_length", length}};
  if (theta1) c["theta1"] = *theta1;
  return c;
}

// The material with the law as its chute calibration, without figures (no widening).
void set_trial(Material& m, double theta2, double length, const double* theta1) {
  ChuteCalibration& c = m.calibration->chute.emplace();
  c.law.coefficients = coefficients_of(theta2, length, theta1);
}

// The fitted deposits precise enough to free theta1.
std::size_t precise_count(const std::vector<StopObservation>& obs) {
  return static_cast<std::size_t>(std::count_if(obs.begin(), obs.end(), [](const auto& o) {
    return !o.held_out && o.error_bar <= kPreciseDeposit * o.reference;
  }));
}

// The check's nominal thickness and whether its band holds the reference, per observation.
void design_figures(const std::vector<StopObservation>& obs, const Material& m,
                    std::vector<double>& thickness, std::vector<bool>& holds) {
  const StoppingThicknessModel& stop = stopping_thickness_models().default_row();
  const Material chute = chute_material(m);
  thickness.clear();
  holds.clear();
  for (const auto& o : obs) {
    const StoppingThicknessBand b = stopping_thickness_band(chute, stop, o.angle);
    thickness.push_back(b.nominal.thickness);
    holds.push_back(b.low <= o.reference && o.reference <= b.high);
  }
}

FitErrors errors_of(const std::vector<double>& thickness, const std::vector<StopObservation>& obs) {
  std::vector<double> references;
  std::vector<bool> held_out;
  for (const auto& o : obs) {
    references.push_back(o.reference);
    held_out.push_back(o.held_out);
  }
  return fit_errors(thickness, references, held_out);
}

std::string deposit_text(const StopObservation& o) {
  return format_quantity(o.reference, "mm", 3) + " at " + format_quantity(o.angle, "deg", 4);
}

// Why no law holds the fitted deposits (with theta1 when it is held); empty when one may.
std::string inadmissible(const std::vector<StopObservation>& obs, std::optional<double> theta1) {
  std::vector<StopObservation> fitted;
  for (const auto& o : obs)
    if (!o.held_out) fitted.push_back(o);
  std::sort(fitted.begin(), fitted.end(),
            [](const StopObservation& a, const StopObservation& b) { return a.angle < b.angle; });
  if (theta1)
    for (const auto& o : fitted)
      if (o.angle <= *theta1)
        return "a deposit of " + deposit_text(o) +
               ", at or below theta1 = " + format_quantity(*theta1, "deg", 4) +
               " (where every layer is static)";
  // Thicker at the steeper inclination beyond both error bars (brackets that overlap may thin).
  for (std::size_t k = 1; k < fitted.size(); ++k)
    if (fitted[k].reference - fitted[k].error_bar >=
        fitted[k - 1].reference + fitted[k - 1].error_bar)
      return "the deposits do not thin as the plane steepens (" + deposit_text(fitted[k - 1]) +
             ", " + deposit_text(fitted[k]) + "): no Pouliquen law holds them";
  return {};
}

// Least squares over p = (log(tan theta2 - tan of the steepest fitted angle), log L) and, when
// theta1 is fitted, q with tan theta1 = tan(shallowest fitted angle) / (1 + e^q) (so theta1
// stays below every fitted deposit); fills f's after values, or throws when the law runs away.
void fit_coefficients(const std::vector<StopObservation>& obs, Material& m, StopLawFit& f) {
  std::vector<std::size_t> fitted;
  std::vector<double> weight;
  double steepest = 0.0, shallowest = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < obs.size(); ++i)
    if (!obs[i].held_out) {
      fitted.push_back(i);
      weight.push_back(std::max(kFloorUncertainty, obs[i].error_bar / obs[i].reference));
      steepest = std::max(steepest, std::tan(obs[i].angle));
      shallowest = std::min(shallowest, std::tan(obs[i].angle));
    }
  const StoppingThicknessModel& stop = stopping_thickness_models().default_row();
  // theta2 kept short of 90 deg (where the law has no meaning); a fit that runs into the cap
  // is refused below.
  const double widest_gap = std::tan(0.5 * (kSteepestTheta2 + 90.0 * kDegree)) - steepest;
  struct Law {
    double theta2, length, theta1;  // theta1: the material's when held
  };
  const auto law_of = [&](std::span<const double> p) {
    return Law{std::atan(steepest + std::min(std::exp(p[0]), widest_gap)), std::exp(p[1]),
               f.theta1_fitted ? std::atan(shallowest / (1.0 + std::exp(p[2]))) : f.theta1_before};
  };
  const auto residuals = [&](std::span<const double> p, std::span<double> r) {
    const Law law = law_of(p);
    set_trial(m, law.theta2, law.length, f.theta1_fitted ? &law.theta1 : nullptr);
    const Material chute = chute_material(m);
    for (std::size_t k = 0; k < fitted.size(); ++k) {
      const StopObservation& o = obs[fitted[k]];
      const double h =
          stop.evaluate(pouliquen_law_of(*chute.surface_flow), chute, o.angle).thickness;
      r[k] = std::log(h / o.reference) / weight[k];
    }
  };
  const double start_gap = std::tan(f.theta2_before) - steepest;
  std::vector<double> start{std::log(start_gap > 0.0 ? start_gap : 0.1), std::log(f.length_before)};
  if (f.theta1_fitted) {
    const double ratio = shallowest / std::tan(f.theta1_before);
    start.push_back(ratio > 1.0 ? std::log(ratio - 1.0) : 0.0);
  }
  const LeastSquaresFit fit = least_squares(residuals, start, fitted.size());
  const Law law = law_of(fit.parameters);
  if (!(law.theta2 < kSteepestTheta2))
    throw std::runtime_error(
        "the deposits thin more slowly with the inclination than any theta2 below 89 deg allows "
        "with theta1 = " +
        format_quantity(law.theta1, "deg", 4) +
        " (a rung whose layers stop like a steeper theta1)");
  f.theta2_after = law.theta2;
  f.length_after = law.length;
  const double tan2 = std::tan(law.theta2);
  f.theta2_error = (tan2 - steepest) * fit.standard_errors[0] / (1.0 + tan2 * tan2);
  f.length_error = law.length * fit.standard_errors[1];
  if (f.theta1_fitted) {
    f.theta1_after = law.theta1;
    // d theta1 / dq = -tan theta1 (1 - tan theta1 / tan shallowest) / (1 + tan^2 theta1)
    const double t1 = std::tan(law.theta1);
    f.theta1_error = t1 * (1.0 - t1 / shallowest) * fit.standard_errors[2] / (1.0 + t1 * t1);
  }
}

}  // namespace

StopLawFit fit_stop_law(const std::vector<StopObservation>& obs, Material m) {
  if (std::none_of(obs.begin(), obs.end(), [](const StopObservation& o) { return !o.held_out; }))
    throw std::invalid_argument("a stopping-thickness fit needs observations to fit");
  if (!m.surface_flow)
    throw std::invalid_argument("a stopping-thickness fit needs the material's [surface_flow]");
  if (!m.calibration) m.calibration.emplace();
  m.calibration->chute.reset();
  StopLawFit f;
  f.theta1_before = f.theta1_after = m.surface_flow->theta1;
  f.theta1_fitted = precise_count(obs) >= kFittedForTheta1;
  f.theta2_before = f.theta2_after = m.surface_flow->theta2;
  f.length_before = f.length_after = m.surface_flow->stop_length;
  design_figures(obs, m, f.thickness_before, f.band_holds_before);
  f.failure =
      inadmissible(obs, f.theta1_fitted ? std::nullopt : std::optional<double>(f.theta1_before));
  if (f.failure.empty()) try {
      Material trial = m;
      fit_coefficients(obs, trial, f);
    } catch (const std::exception& e) {
      f.failure = e.what();
    }
  if (!f.failure.empty()) {
    f.theta1_after = f.theta1_before;
    f.theta1_fitted = false;
    f.theta2_after = f.theta2_before;
    f.length_after = f.length_before;
    f.theta2_error = f.length_error = 0.0;
  }
  const double* theta1 = f.theta1_fitted ? &f.theta1_after : nullptr;
  const FitErrors before = errors_of(f.thickness_before, obs);
  f.fit_rms_before = before.fit_rms;
  f.held_out_max_before = before.held_out_max;
  Material calibrated = m;
  set_trial(calibrated, f.theta2_after, f.length_after, theta1);
  std::vector<bool> unused;
  design_figures(obs, calibrated, f.thickness_after, unused);
  const FitErrors after = errors_of(f.thickness_after, obs);
  f.fit_rms_after = after.fit_rms;
  f.held_out_max_after = after.held_out_max;

  f.law.coefficients = coefficients_of(f.theta2_after, f.length_after, theta1);
  set_error_figures(
      f.law, before, after,
      std::any_of(obs.begin(), obs.end(), [](const StopObservation& o) { return o.held_out; }));
  // The band after: the check's with the calibration's figures (widened by its error).
  calibrated.calibration->chute->law = f.law;
  design_figures(obs, calibrated, f.thickness_after, f.band_holds_after);
  return f;
}

}  // namespace feedflow
