#pragma once
// Fits Pouliquen's stopping-thickness law (theta2 and L of h_stop = L (tan theta2 - tan theta) /
// (tan theta - tan theta1); theta1 too from three fitted inclinations on, else held at the
// material's) to a full rung's deposits on an inclined plane over its inclination, by least squares
// on the log of the thickness, each point weighted by its reference's relative uncertainty (at
// least kFloorUncertainty), through the chute check's own evaluation (so `design` reproduces the
// fit), and measures the check before and after on the fitted and the held-out inclinations.
// Deposits no such law can hold (thicker at a steeper inclination, thinning more slowly than any
// theta2 below 89 deg allows, a deposit at or below a held theta1) leave the law as published and
// say why.
#include <string>
#include <vector>

#include "models/material/material.hpp"

namespace feedflow {

// One design point: the plane's inclination and the full rung's deposit there.
struct StopObservation {
  double angle = 0.0;      // [rad]
  double reference = 0.0;  // [m] deposit thickness mid-ramp, normal to the ramp
  double error_bar = 0.0;  // [m]
  bool held_out = false;
};

// Fitted inclinations from which theta1 is fitted too (below, the material's is held), each
// deposit known to kPreciseDeposit of itself: a wider bracket (a search cut short early) still
// counts in the fit but leaves theta1 free to run off.
constexpr std::size_t kFittedForTheta1 = 3;
constexpr double kPreciseDeposit = 0.25;

struct StopLawFit {
  bool theta1_fitted = false;                      // else held at the material's
  double theta1_before = 0.0, theta1_after = 0.0;  // [rad]
  double theta1_error = 0.0;                       // standard error [rad] when fitted
  double theta2_before = 0.0, theta2_after = 0.0;  // [rad]
  double length_before = 0.0, length_after = 0.0;  // [m] L
  double theta2_error = 0.0,
         length_error = 0.0;  // standard errors [rad], [m] (inf: no spare point)
  std::vector<double> thickness_before, thickness_after;       // [m] the check's nominal h_stop
  std::vector<bool> band_holds_before, band_holds_after;       // its band holds the reference
  double fit_rms_before = 0.0, fit_rms_after = 0.0;            // relative error, fitted points
  double held_out_max_before = 0.0, held_out_max_after = 0.0;  // largest relative error, held out
  std::string failure;  // why the law kept its published theta2 and L
  CalibratedModel law;  // coefficients and figures, for the material
};

// `material`: the published material (its own chute calibration ignored), with [surface_flow].
// Throws std::invalid_argument without fitted observations or without [surface_flow].
StopLawFit fit_stop_law(const std::vector<StopObservation>& observations, Material material);

}  // namespace feedflow
