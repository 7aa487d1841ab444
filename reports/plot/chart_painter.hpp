#pragma once
// Draws a Chart with cairo: axes with units, ticks, grid, series, legend. Vector output on a
// PDF surface, pixels on an image surface.
#include <cairo.h>

#include <filesystem>
#include <string>

#include "models/core/chart.hpp"

namespace feedflow {

// Paints `chart` into the rectangle (x, y, width, height) of `cr`, in the context's units.
void paint_chart(cairo_t* cr, const Chart& chart, double x, double y, double width, double height);

// The chart as PNG bytes, `width` x `height` pixels (for HTML reports).
std::string chart_png(const Chart& chart, int width, int height);

// "semi-angle [deg]", or the label alone for pure numbers.
std::string axis_title(const ChartAxis& axis);

}  // namespace feedflow
