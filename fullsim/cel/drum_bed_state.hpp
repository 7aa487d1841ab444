#pragma once
// The bed state of the CEL drum at one time, what the regime is classified from
// (fullsim/common/drum_bed_regime.hpp): the particle rung's measures with the cells' mass for
// particle counts. The surface is the volume-fraction-0.5 line over the whole chord
// (drum_surface). In flight is material off the shell in cells clear of the bed (no cell within
// two cells at least half full: thrown, not the bed's own mixed surface cells); over the top, above
// 0.8 R; moving with the shell, within 0.1 omega R of the shell's rigid turn; the shell layer is
// the cells whose centre is within one cell of the shell and, within the chord, two cells below the
// surface (where the bed lies on the shell, not where the flowing layer runs into it at the chord's
// ends), its speed along the turn over omega R. Up and across are taken against the current gravity
// direction (the solver may turn with the shell). The surface's bulge is fitted as on the particle
// rung, from the surface averaged over the steady window (`chord_profile` at fixed fractions of
// the chord, averaged by the caller); the angle's swing is the series' (steady_angle).
#include <vector>

#include "fullsim/cel/drum_scene.hpp"
#include "fullsim/common/drum_bed_regime.hpp"

namespace feedflow::cel {

// `surface`: drum_surface(solver, section, 1.0), the whole chord; `speed`: the shell's angular
// velocity [rad/s] (counter-clockwise positive; 0 before it starts). The state's surface_bulge
// is that of this one surface.
DrumBedState drum_bed_state(const CelSolver& solver, const DrumSection& section,
                            const FreeSurface& surface, double speed);

// The surface's height (up, from the centre) at a station across the chord [m], linear between
// its points; NaN outside them. surface_heights: the same at each station.
double surface_height(const FreeSurface& surface, double station);
std::vector<double> surface_heights(const FreeSurface& surface,
                                    const std::vector<double>& stations);

// The surface's profile at fixed fractions of its chord (-1: its first point, 1: its last): the
// chord's ends and the heights there [m], what a time average of the surface is made of. No
// surface (fewer than two points): `found` false, all zero.
struct ChordProfile {
  bool found = false;
  double low = 0.0, high = 0.0;  // across the drum [m]
  std::vector<double> height;    // at each fraction [m]
};
ChordProfile chord_profile(const FreeSurface& surface, const std::vector<double>& fractions);

}  // namespace feedflow::cel
