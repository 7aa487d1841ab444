#pragma once
// The free surface of a drum's bed fitted, on both rungs: the dynamic angle of repose (seed
// section 3.3: "AoR = free-surface slope at steady state") is the slope of a least-squares line
// through the surface points of the central part of the chord (reduced_models.md section 4:
// "define the AoR as the mid-chord slope"; the ends of the chord touch the shell). The bulge is
// the largest distance between a cubic fitted to the inner 80 % of the chord and that line, over
// the drum radius: ~0 for the flat surface of rolling, large for the S- or kidney-shaped surface
// of cascading. Points on the cross-section: x across the drum, z up, the axis at the origin.
#include <cstddef>
#include <vector>

namespace feedflow {

struct SurfacePoint {
  double x = 0.0;  // across the drum [m]
  double z = 0.0;  // up [m]
};

struct DrumSurfaceFit {
  bool valid = false;        // enough surface points (at least 4 in the central part)
  double slope_angle = 0.0;  // atan(dz/dx) of the central line [rad]
  double intercept = 0.0;    // z of the line at x = 0 [m]
  double bulge = 0.0;        // max |cubic - line| over the chord / drum radius [-]
  double chord_low = 0.0;    // x range of the surface points [m]
  double chord_high = 0.0;
  std::size_t points = 0;  // surface points in the central fit
};

// The fit over the central `central_fraction` of the chord (0.6: the middle 60 %).
DrumSurfaceFit fit_drum_surface(const std::vector<SurfacePoint>& surface, double drum_radius,
                                double central_fraction = 0.6);

}  // namespace feedflow
