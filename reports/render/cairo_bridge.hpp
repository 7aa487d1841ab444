#pragma once
// Moving pixels between RgbaImage and cairo image surfaces (for PNG files and for the text and
// overlays that cairo draws onto a rendered snapshot). Internal to reports/render.
#include <cairo.h>

#include <memory>

#include "reports/render/rgba_image.hpp"

namespace feedflow::render {

struct CairoSurfaceRelease {
  void operator()(cairo_surface_t* s) const { cairo_surface_destroy(s); }
};
using CairoSurface = std::unique_ptr<cairo_surface_t, CairoSurfaceRelease>;

struct CairoContextRelease {
  void operator()(cairo_t* c) const { cairo_destroy(c); }
};
using CairoContext = std::unique_ptr<cairo_t, CairoContextRelease>;

// A new ARGB32 surface holding `image`. Throws std::runtime_error if cairo cannot allocate it.
CairoSurface to_cairo_surface(const RgbaImage& image);

// The pixels of an image surface (any of cairo's 24/32-bit formats) as straight RGBA.
RgbaImage from_cairo_surface(cairo_surface_t* surface);

}  // namespace feedflow::render
