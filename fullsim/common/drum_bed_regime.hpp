#pragma once
// The bed behaviour (regime) of a rotating drum classified from its measured state, not from
// the Froude number: Mellmann (2001, Powder Technol. 118:251) defines the regimes by how the
// bed moves, and reduced_models.md section 4 warns that his Froude bands do not match the
// seed's labels, so the full rungs decide from what the bed does:
//   centrifuging: the bed turns with the shell as a solid body and covers the top of the drum
//                 (Fr >= 1 at the shell, >= 1/sqrt(1 - f) for the whole bed);
//   cataracting:  particles leave the bed and fly through the free space above it;
//   slipping:     the bed slides on the shell as a block (shell speed not passed on);
//   slumping:     the bed turns with the shell as a solid body most of the time and the
//                 surface angle swings (discrete avalanches between a static and a dynamic
//                 angle) instead of holding;
//   cascading:    continuous flow with particles leaving the surface in short flights from
//                 the raised shoulder, or a clearly curved (kidney or S-shaped) surface;
//   rolling:      continuous flow in contact: a steady surface, next to no particles in flight.
// On the coarse twin (R = 3 mm, 18 mm slab) the time-averaged surface bends by 10 to 14 % of R
// at 10 rpm and 15 to 25 % at 50 rpm (runs differing only in the packing), so the shape alone
// does not separate rolling from cascading reliably there; the particles in flight do (0.01 to
// 0.05 % at 10 rpm, 0.30 % at 50 rpm with the former lattice fill; rain-filled: bend 15 % and
// 0.026 % in flight at 10 rpm, bend 26 % and 0.13 % at 50 rpm). The criterion counts particles
// more than 3 radii above the surface line, so it depends on the resolution and on the bed: the
// seed-size 9 mm slab at 20 rpm measured 0.098 % lattice-filled (rolling, 41.0 deg) and 0.14 %
// rain-filled (cascading, 43.3 deg; the seed labels 20 rpm rolling). Calibrate against a run
// of the size you use.
// The thresholds are stated in DrumRegimeCriteria (their defaults are the values used in the
// tests on the seed's 10, 50 and 300 rpm labels).
#include <string>

namespace feedflow {

enum class DrumBedRegime { slipping, slumping, rolling, cascading, cataracting, centrifuging };
const char* to_string(DrumBedRegime regime);

// Averages over the steady part of a run (or one state).
struct DrumBedState {
  double surface_bulge = 0.0;  // max |cubic - line| of the surface over the radius [-]
  double angle_swing = 0.0;    // peak-to-peak of the surface angle over the window [rad]
  // Of the bed in flight, off the shell: more than 3 particle radii above the fitted surface
  // line (DEM), in cells clear of the bed by two cells (CEL) [-].
  double airborne_fraction = 0.0;
  double over_top_fraction = 0.0;    // of the bed above 0.8 R (over the top of the drum) [-]
  double solid_body_fraction = 0.0;  // of the bed moving within 0.1 omega R of omega x r [-]
  double shell_speed_ratio = 1.0;    // mean tangential speed of the shell layer / shell speed [-]
  double particles = 0.0;  // particles in the bed (the fractions' denominator); 0: a continuum [-]
};

struct DrumRegimeCriteria {
  double centrifuging_solid_body = 0.8;  // and over_top_fraction above:
  double centrifuging_over_top = 0.08;
  double cataracting_airborne = 0.03;  // 3 % of the bed in flight
  double cascading_airborne = 0.001;   // 0.1 %, and at least one particle on average (a
                                       // small bed's fraction below one particle is noise)
  double slipping_shell_speed = 0.5;   // the shell layer moves at less than half the shell
  double slumping_solid_body = 0.75;   // and the angle swinging peak-to-peak by more than:
  double slumping_swing = 0.09;        // [rad] (5 deg)
  double cascading_bulge = 0.25;       // the mean surface bending by 25 % of R from its line
};

struct DrumRegimeCall {
  DrumBedRegime regime = DrumBedRegime::rolling;
  std::string reason;  // which measured quantity decided, with its value and threshold
};

DrumRegimeCall classify_drum_bed(const DrumBedState& state,
                                 const DrumRegimeCriteria& criteria = {});

}  // namespace feedflow
