#pragma once
// Fits each hopper.discharge row's free coefficients (Beverloo's C and k, the factor on a
// theory's rate) to full-rung discharge rates by least squares on the relative error, each
// point weighted by its reference's relative uncertainty (at least kFloorUncertainty), through
// the design check's own evaluation (so the design check reproduces the fit exactly), and
// measures the rows and the design band before and after, on the fitted and the held-out points.
// A coefficient the fit takes out of its physical range (Beverloo's k past 3) is held at its
// published value and the others are fitted again: a curve through the points with meaningless
// coefficients would not extrapolate.
#include <string>
#include <vector>

#include "designer/design/hopper_estimates.hpp"

namespace feedflow {

// The relative uncertainty a reference is weighted with at least (a CEL level without an error
// bar, a DEM run with a tight interval): 2 %.
inline constexpr double kFloorUncertainty = 0.02;
// A reference less sure than this (error bar over value) does not enter a fit: 50 %.
inline constexpr double kUsableUncertainty = 0.5;

// One design point: the hopper at its outlet and semi-angle, and the full rung's rate there.
struct DischargeObservation {
  Hopper hopper;
  double reference = 0.0;  // [kg/s], the whole outlet (as results.json's mass_flow_rate)
  double error_bar = 0.0;  // [kg/s]
  bool held_out = false;
};

struct DischargeRowFit {
  const DischargeModel* row = nullptr;
  std::vector<double> before, after;           // coefficients, published and fitted
  std::vector<double> standard_errors;         // of the fitted ones (0 for one held at its published value)
  std::vector<std::string> held;               // coefficients held at their published value, and why
  std::vector<double> rate_before, rate_after; // [kg/s] per observation
  double fit_rms_before = 0.0, fit_rms_after = 0.0;          // relative error, fitted points
  double held_out_max_before = 0.0, held_out_max_after = 0.0; // largest relative error, held-out points
  std::string failure;                         // why the row kept its published coefficients
};

struct DischargeFit {
  std::vector<DischargeRowFit> rows;           // the rows that apply to the geometry
  DischargeCalibration calibration;            // the fitted rows, for the material
  std::vector<double> design_before, design_after;        // the design check's q_m [kg/s]
  std::vector<bool> band_holds_before, band_holds_after;  // its band holds the reference
};

// `material`: the published material (its own calibration ignored); `models`: the design
// check's rows (the default row's fit is what `design` reports). Throws std::invalid_argument
// without fitted observations or with hoppers of two geometries.
DischargeFit fit_discharge(const std::vector<DischargeObservation>& observations, HopperMaterial material,
                           const HopperModels& models = {});

// |a / b - 1|.
double relative_error(double a, double b);
// A relative error as a figure: "4.1 %".
std::string percent(double relative);

// A model's errors against a fit's references: the rms relative error over the fitted points and
// the largest over the held-out ones (0 without any).
struct FitErrors {
  double fit_rms = 0.0, held_out_max = 0.0;
};
FitErrors fit_errors(const std::vector<double>& values, const std::vector<double>& references,
                     const std::vector<bool>& held_out);

// A fit's errors as a calibrated model's figures: fit_rms_error (and _before) and, when points
// were held out, held_out_max_error (and _before).
void set_error_figures(CalibratedModel& m, const FitErrors& before, const FitErrors& after,
                       bool held_out);

}  // namespace feedflow
