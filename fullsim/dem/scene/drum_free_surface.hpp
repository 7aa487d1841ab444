#pragma once
// The free surface of a DEM drum's bed: its points, fitted by fullsim/common/drum_surface_fit.hpp
// (the dynamic angle and the bulge). Works on the cross-section: x across the drum, z up, the
// axis at the origin. The bed is cut into columns one particle diameter wide; a column's
// surface point is its highest particle still in contact with the bed below it (gap to the next
// lower centre below 2.5 radii, so particles in free flight above the bed are not surface
// points; a column topped at the shell has none).
#include <cstddef>
#include <functional>
#include <vector>

#include "fullsim/common/drum_surface_fit.hpp"

namespace feedflow {

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

}  // namespace feedflow
