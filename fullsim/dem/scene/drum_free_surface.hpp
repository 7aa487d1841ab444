#pragma once
// The free surface of a drum's bed and its slope, the dynamic angle of repose (seed section
// 3.3: "AoR = free-surface slope at steady state"). Works on the cross-section: x across the
// drum, z up, the axis at the origin. The bed is cut into columns one particle diameter
// wide; a column's surface point is its highest particle still in contact
// with the bed below it (gap to the next lower centre below 2.5 radii, so particles in free
// flight above the bed are not surface points; a column topped at the shell has none). The dynamic angle is the slope of a
// least-squares line through the surface points of the central part of the chord (reduced_
// models.md section 4: "define the AoR as the mid-chord slope"; the ends of the chord touch the
// shell). The bulge is the largest distance between a cubic fitted to the whole chord and that
// line, over the drum radius: ~0 for the flat surface of rolling, large for the S- or kidney-
// shaped surface of cascading.
#include <cstddef>
#include <functional>
#include <vector>

namespace feedflow {

struct SurfacePoint {
  double x = 0.0;  // across the drum [m]
  double z = 0.0;  // up [m]
};

struct DrumSurfaceFit {
  bool valid = false;          // enough surface points (at least 4 in the central part)
  double slope_angle = 0.0;    // atan(dz/dx) of the central line [rad]
  double intercept = 0.0;      // z of the line at x = 0 [m]
  double bulge = 0.0;          // max |cubic - line| over the chord / drum radius [-]
  double chord_low = 0.0;      // x range of the surface points [m]
  double chord_high = 0.0;
  std::size_t points = 0;      // surface points in the central fit
};

// The tops of the bed's columns, what the surface points are found from: per column its
// particle count and its `depth` highest centres in descending order, padded with -infinity.
// Columns of several ranks' particles merge by summing the counts and keeping the highest
// `depth` of the lists (BedView::highest); the surface found from the merged tops is that of
// the whole bed.
struct ColumnTops {
  std::size_t depth = 0;
  std::vector<double> count;  // per column
  std::vector<double> z;      // per column, `depth` values [m]
};
ColumnTops column_tops(const std::vector<SurfacePoint>& particles, double particle_radius,
                       double drum_radius, std::size_t depth);

// The surface points of the columns. `undetermined` gets the number of columns whose list is
// too short to tell (more particles than the list holds, and no surface point in it); they
// give no point, and deeper lists settle them.
std::vector<SurfacePoint> surface_points(const ColumnTops& tops, double particle_radius,
                                         double drum_radius, std::size_t& undetermined);

// The surface points of a bed given as cross-section positions (x, z) of particles of
// `particle_radius` in a drum of `drum_radius`: from lists 16 deep, deepened until every column
// is told. `merge` makes the whole bed's tops of this rank's (none alone; collective).
std::vector<SurfacePoint> bed_surface_points(const std::vector<SurfacePoint>& particles,
                                             double particle_radius, double drum_radius,
                                             const std::function<void(ColumnTops&)>& merge = {});

// The fit over the central `central_fraction` of the chord (0.6: the middle 60 %).
DrumSurfaceFit fit_drum_surface(const std::vector<SurfacePoint>& surface, double drum_radius,
                                double central_fraction = 0.6);

}  // namespace feedflow
