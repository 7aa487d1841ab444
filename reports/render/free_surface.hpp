#pragma once
// The free surface of a continuum field: the contour where the volume fraction crosses the
// fill threshold, found by marching squares. The contour runs on the grid of cell corners,
// where each corner takes the mean volume fraction of the (up to four) cells around it inside
// the grid; so a sharp material/void interface gives an outline on the cell edges, matching the
// filled cells drawn, and the outline ends at the grid border rather than running along it.
#include <functional>
#include <span>
#include <vector>

#include "reports/render/scene.hpp"

namespace feedflow::render {

struct Point2 {
  double x = 0.0;
  double y = 0.0;
};

// A piece of outline in the plane of the grid: (x0, y0) to (x1, y1), metres.
struct OutlineSegment {
  double x0 = 0.0;
  double y0 = 0.0;
  double x1 = 0.0;
  double y1 = 0.0;
};

// The `level` contour of the volume fraction (the grid's fill_threshold by default); saddle
// squares are resolved by the mean of their four corners. Order: squares row by row.
std::vector<OutlineSegment> free_surface_outline(const FieldGrid& field);
std::vector<OutlineSegment> free_surface_outline(const FieldGrid& field, double level);

// The filled part of each cell, bounded by the same contour: `visit(i, j, polygon)` is called
// for every cell (i, j) with material, with one or two convex polygons (counter-clockwise) that
// together cover the cell's part inside the fill_threshold contour. A cell inside the surface
// gets its whole square; so filled cells and the outline meet exactly.
void for_each_filled_polygon(
    const FieldGrid& field,
    const std::function<void(int i, int j, std::span<const Point2> polygon)>& visit);

}  // namespace feedflow::render
