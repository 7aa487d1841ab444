#include "reports/render/legend_overlay.hpp"

#include <cairo.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>

#include "reports/render/cairo_bridge.hpp"
#include "reports/plot/axis_ticks.hpp"

namespace feedflow::render {

namespace {

constexpr double kInk = 0.1;  // grey level of text and frames

void set_font(cairo_t* cr, double size) {
  cairo_select_font_face(cr, "DejaVu Sans", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
  cairo_set_font_size(cr, size);
}

// Text with its left end at x and its baseline centred vertically on y.
void text_left(cairo_t* cr, double x, double y, const std::string& s) {
  cairo_text_extents_t e;
  cairo_text_extents(cr, s.c_str(), &e);
  cairo_move_to(cr, x - e.x_bearing, y - e.y_bearing - 0.5 * e.height);
  cairo_show_text(cr, s.c_str());
}

// Text shrunk if needed to fit `max_width`, left end at x, baseline at y.
void title(cairo_t* cr, double x, double y, double size, double max_width, const std::string& s) {
  set_font(cr, size);
  cairo_text_extents_t e;
  cairo_text_extents(cr, s.c_str(), &e);
  if (e.x_advance > max_width && e.x_advance > 0.0) set_font(cr, size * max_width / e.x_advance);
  cairo_move_to(cr, x, y);
  cairo_show_text(cr, s.c_str());
  set_font(cr, size);
}

void colour_bar_labels(cairo_t* cr, const SnapshotLayout& layout, const ColourScale& scale) {
  const double f = layout.font_size;
  const PixelRect& bar = layout.colour_bar;
  const PixelRect& panel = layout.legend;
  const double max_width = panel.x + panel.width - bar.x - 0.5 * f;
  title(cr, bar.x, bar.y - 2.0 * f, f, max_width, scale.quantity);
  title(cr, bar.x, bar.y - 0.7 * f, f, max_width, scale.unit.empty() ? "" : "[" + scale.unit + "]");
  // Frame just outside the gradient, so the gradient's pixels keep their exact colours.
  cairo_set_line_width(cr, 1.0);
  cairo_rectangle(cr, bar.x - 0.5, bar.y - 0.5, bar.width + 1.0, bar.height + 1.0);
  cairo_stroke(cr);
  const std::vector<double> ticks = ticks_inside(scale.lo, scale.hi, 6);
  const double step = ticks.size() > 1 ? ticks[1] - ticks[0] : std::max(std::abs(scale.lo), 1.0);
  const double tick_length = 0.4 * f;
  for (double t : ticks) {
    // Row centre of the value: lo at the bottom row's centre, hi at the top row's.
    const double y = bar.y + bar.height - 0.5 - scale.fraction(t) * (bar.height - 1);
    const double x = bar.x + bar.width + 0.5;
    cairo_move_to(cr, x, std::round(y) + 0.5);
    cairo_line_to(cr, x + tick_length, std::round(y) + 0.5);
    cairo_stroke(cr);
    text_left(cr, x + tick_length + 0.3 * f, y, tick_label(t, step));
  }
}

void layer_legend(cairo_t* cr, const SnapshotLayout& layout,
                  const std::vector<std::int32_t>& layers) {
  const double f = layout.font_size;
  const PixelRect& panel = layout.legend;
  const double x = panel.x + f;
  title(cr, x, 2.0 * f, f, panel.width - 1.5 * f, "initial layer");
  const std::size_t shown = std::min<std::size_t>(layers.size(), 16);
  for (std::size_t k = 0; k < shown; ++k) {
    const double y = 3.2 * f + 1.5 * f * static_cast<double>(k);
    const Rgb8 c = layer_colour(layers[k]);
    cairo_rectangle(cr, x, y, f, f);
    cairo_set_source_rgb(cr, c.r / 255.0, c.g / 255.0, c.b / 255.0);
    cairo_fill_preserve(cr);
    cairo_set_source_rgb(cr, kInk, kInk, kInk);
    cairo_set_line_width(cr, 1.0);
    cairo_stroke(cr);
    text_left(cr, x + 1.5 * f, y + 0.5 * f, std::to_string(layers[k]));
  }
  if (layers.size() > shown) text_left(cr, x, 3.2 * f + 1.5 * f * shown + 0.5 * f, "...");
}

void scale_bar(cairo_t* cr, const SnapshotLayout& layout, double metres_per_pixel) {
  const double f = layout.font_size;
  const PixelRect& scene = layout.scene;
  const double metres = round_length_below(0.25 * scene.width * metres_per_pixel);
  const double pixels = metres / metres_per_pixel;
  const double x0 = scene.x + 1.5 * f;
  const double y = scene.y + scene.height - 1.2 * f;
  const double thickness = std::max(2.0, std::round(f / 5.0));
  const std::string label = length_label(metres);
  // A halo in white keeps the bar readable over particles.
  for (int pass = 0; pass < 2; ++pass) {
    const double grow = pass == 0 ? 0.25 * f : 0.0;
    const double ink = pass == 0 ? 1.0 : kInk;
    cairo_set_source_rgb(cr, ink, ink, ink);
    cairo_rectangle(cr, x0 - grow, y - 0.5 * thickness - grow - 0.5 * f, pixels + 2 * grow,
                    thickness + 2 * grow + 0.5 * f);
    if (pass == 0) {
      cairo_text_extents_t e;
      cairo_text_extents(cr, label.c_str(), &e);
      cairo_rectangle(cr, x0 + 0.5 * pixels - 0.5 * e.width - grow, y - 1.9 * f - grow,
                      e.width + 2 * grow, 1.2 * f + 2 * grow);
      cairo_fill(cr);
      continue;
    }
    cairo_new_path(cr);
    cairo_rectangle(cr, x0, y - 0.5 * thickness, pixels, thickness);
    cairo_rectangle(cr, x0, y - 0.5 * thickness - 0.5 * f, thickness, 0.5 * f);  // end ticks
    cairo_rectangle(cr, x0 + pixels - thickness, y - 0.5 * thickness - 0.5 * f, thickness, 0.5 * f);
    cairo_fill(cr);
    cairo_text_extents_t e;
    cairo_text_extents(cr, label.c_str(), &e);
    cairo_move_to(cr, x0 + 0.5 * pixels - 0.5 * e.width - e.x_bearing, y - 0.9 * f);
    cairo_show_text(cr, label.c_str());
  }
}

}  // namespace

void paint_colour_gradient(RgbaImage& image, const PixelRect& bar) {
  for (int row = 0; row < bar.height; ++row) {
    // Bottom row: lo; top row: hi.
    const double t = bar.height > 1 ? 1.0 - static_cast<double>(row) / (bar.height - 1) : 0.5;
    const Rgb8 c = viridis(t);
    for (int col = 0; col < bar.width; ++col) {
      const int x = bar.x + col;
      const int y = bar.y + row;
      if (x >= 0 && y >= 0 && x < image.width && y < image.height)
        image.set(x, y, {c.r, c.g, c.b, 255});
    }
  }
}

void draw_legend(RgbaImage& image, const SnapshotLayout& layout, const LegendText& text) {
  CairoSurface surface = to_cairo_surface(image);
  {
    CairoContext context(cairo_create(surface.get()));
    cairo_t* cr = context.get();
    set_font(cr, layout.font_size);
    cairo_set_source_rgb(cr, kInk, kInk, kInk);
    if (text.scale != nullptr && layout.colour_bar.width > 0)
      colour_bar_labels(cr, layout, *text.scale);
    if (!text.layers.empty() && layout.legend.width > 0) layer_legend(cr, layout, text.layers);
    if (text.metres_per_pixel > 0.0) scale_bar(cr, layout, text.metres_per_pixel);
    if (cairo_status(cr) != CAIRO_STATUS_SUCCESS) {
      throw std::runtime_error(std::string("cairo failed drawing the snapshot legend: ") +
                               cairo_status_to_string(cairo_status(cr)));
    }
  }
  image = from_cairo_surface(surface.get());
}

std::string length_label(double metres) {
  char text[64];
  if (metres >= 1.0)
    std::snprintf(text, sizeof text, "%g m", metres);
  else
    std::snprintf(text, sizeof text, "%g mm", metres * 1000.0);
  return text;
}

}  // namespace feedflow::render
