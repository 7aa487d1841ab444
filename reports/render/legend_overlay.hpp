#pragma once
// The annotations drawn over a rendered scene: the colour bar with its ticks and the quantity
// with its unit, the legend of layer colours, and the scale bar. The gradient is written
// straight into the pixels (exact colour-map values); text, ticks and frames go through cairo.
#include <cstdint>
#include <vector>

#include "reports/render/colour_map.hpp"
#include "reports/render/rgba_image.hpp"
#include "reports/render/snapshot_layout.hpp"

namespace feedflow::render {

// Fills `bar` with viridis, 0 (the scale's lo) on the bottom row and 1 (hi) on the top row.
void paint_colour_gradient(RgbaImage& image, const PixelRect& bar);

// Everything cairo draws. `layers` lists the layer ids to explain (empty: no layer legend);
// `metres_per_pixel` <= 0 leaves out the scale bar.
struct LegendText {
  const ColourScale* scale = nullptr;  // the colour bar's labels, or null
  std::vector<std::int32_t> layers;
  double metres_per_pixel = 0.0;
};

// Throws std::runtime_error when cairo fails.
void draw_legend(RgbaImage& image, const SnapshotLayout& layout, const LegendText& text);

// "200 mm", "1 m", "0.5 mm": a length for the scale bar label.
std::string length_label(double metres);

}  // namespace feedflow::render
