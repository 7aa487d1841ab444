#pragma once
// Rotating drum: Froude number, critical speed, the segment geometry of the fill, the bed
// behaviour (regime) from material-calibrated Froude thresholds, the full-bed centrifuging
// criterion and the no-slip wall criterion (reduced_models.md section 4).
#include <array>
#include <optional>
#include <string>

#include "models/equipment/drum.hpp"

namespace feedflow {

// Fr = omega^2 R/g = (n/n_c)^2.
double drum_froude(double diameter, double speed);
// n_c = sqrt(2 g/D) [rad/s]: the speed at which the outer layer centrifuges.
double drum_critical_speed(double diameter);

// The flat-surface segment of a fill fraction f: f = (2 eps - sin 2 eps)/(2 pi), eps the half
// angle of the chord seen from the axis (GSL Brent root). Half-chord L_c = R sin eps; bed centroid
// r_g = 4 R sin^3 eps/[3 (2 eps - sin 2 eps)] from the axis.
struct FillSegment {
  double half_angle;     // eps [rad]
  double half_chord;     // L_c [m]
  double centroid_radius;  // r_g [m]
};
FillSegment fill_segment(double diameter, double fill_fraction);

enum class DrumRegime { Slumping, Rolling, Cascading, Cataracting, Centrifuging };
const char* to_string(DrumRegime regime);

// Upper Froude bounds of each regime. NOT Mellmann's recalled bands: the defaults are chosen
// inside the windows the seed's labels allow for milled pine in the seed drum (D = 0.145 m):
// 10 and 20 rpm roll (Fr 0.0081, 0.0324), 50 rpm cascades (0.203), 300 rpm centrifuges (7.3).
// Calibrate them per material; slumping_to_rolling has no seed evidence (Mellmann's order).
struct DrumRegimeThresholds {
  double slumping_to_rolling = 1e-4;
  double rolling_to_cascading = 0.1;        // in (0.0324, 0.203] for the seed's labels
  double cascading_to_cataracting = 0.5;    // above 0.203
  double centrifuging = 1.0;                // outer layer at the wall: Fr >= 1
};

// The boundaries between regimes in Fr, slowest first: "slumping | rolling", ...,
// "centrifuging (outer layer)".
struct RegimeBoundary {
  const char* name;
  double froude;
};
std::array<RegimeBoundary, 4> regime_boundaries(const DrumRegimeThresholds& t);

struct DrumRegimeAssessment {
  double froude = 0.0;
  double critical_speed = 0.0;               // [rad/s]
  DrumRegime regime = DrumRegime::Rolling;
  double full_bed_centrifuging_froude = 0.0;  // 1/sqrt(1 - f)
  bool full_bed_centrifuges = false;          // Fr >= 1/sqrt(1 - f)
  // No slip at the shell needs tan(wall friction) > (r_g/R) sin(beta_d); empty when the drum has
  // no wall friction angle or no angle of repose was given.
  std::optional<bool> wall_slips;
  double no_slip_friction = 0.0;  // (r_g/R) sin(beta_d), 0 without an angle of repose
  std::string words;
};

// Throws std::invalid_argument for a drum with D <= 0, speed < 0 or f outside (0, 1), and for
// thresholds that do not rise.
DrumRegimeAssessment assess_drum_regime(const Drum& drum, const DrumRegimeThresholds& thresholds,
                                        std::optional<double> angle_of_repose = std::nullopt);

}  // namespace feedflow
