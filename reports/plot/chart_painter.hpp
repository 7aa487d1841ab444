#pragma once
// Draws a Chart with cairo: axes with units, ticks, grid, series, legend. Vector output on a
// PDF surface, pixels on an image surface.
#include <cairo.h>

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "models/core/chart.hpp"

namespace feedflow {

// Paints `chart` into the rectangle (x, y, width, height) of `cr`, in the context's units.
void paint_chart(cairo_t* cr, const Chart& chart, double x, double y, double width, double height);

// The chart as PNG bytes, `width` x `height` pixels (for HTML reports).
std::string chart_png(const Chart& chart, int width, int height);

// Where the legend box goes: of the plot area's four inner corners (top right first, then top
// left, bottom right, bottom left), the first that covers the fewest of `marks` (the series'
// points and their segments sampled, in device units). Returns the box's top-left corner.
struct LegendPlace {
  double x = 0.0, y = 0.0;
};
struct DeviceBox {
  double left = 0.0, top = 0.0, right = 0.0, bottom = 0.0;
};
LegendPlace legend_place(const DeviceBox& plot, double box_width, double box_height,
                         const std::vector<std::pair<double, double>>& marks);

// "semi-angle [deg]", or the label alone for pure numbers.
std::string axis_title(const ChartAxis& axis);

}  // namespace feedflow
