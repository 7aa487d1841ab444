#include "reports/render/cairo_bridge.hpp"

#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <string>

namespace feedflow::render {

// Cairo's ARGB32 is one native-endian 32-bit word per pixel, alpha premultiplied.
CairoSurface to_cairo_surface(const RgbaImage& image) {
  CairoSurface surface(cairo_image_surface_create(CAIRO_FORMAT_ARGB32, image.width, image.height));
  if (cairo_surface_status(surface.get()) != CAIRO_STATUS_SUCCESS) {
    throw std::runtime_error("cairo cannot create a " + std::to_string(image.width) + "x" +
                             std::to_string(image.height) + " image surface");
  }
  cairo_surface_flush(surface.get());
  unsigned char* data = cairo_image_surface_get_data(surface.get());
  const int stride = cairo_image_surface_get_stride(surface.get());
  for (int y = 0; y < image.height; ++y) {
    auto* row = reinterpret_cast<std::uint32_t*>(data + static_cast<std::ptrdiff_t>(y) * stride);
    for (int x = 0; x < image.width; ++x) {
      const Rgba8 c = image.at(x, y);
      const auto premultiply = [a = c.a](std::uint32_t v) { return (v * a + 127) / 255; };
      row[x] = (std::uint32_t{c.a} << 24) | (premultiply(c.r) << 16) | (premultiply(c.g) << 8) |
               premultiply(c.b);
    }
  }
  cairo_surface_mark_dirty(surface.get());
  return surface;
}

RgbaImage from_cairo_surface(cairo_surface_t* surface) {
  cairo_surface_flush(surface);
  const cairo_format_t format = cairo_image_surface_get_format(surface);
  if (format != CAIRO_FORMAT_ARGB32 && format != CAIRO_FORMAT_RGB24) {
    throw std::runtime_error("unsupported cairo pixel format " + std::to_string(format));
  }
  RgbaImage image(cairo_image_surface_get_width(surface), cairo_image_surface_get_height(surface));
  const unsigned char* data = cairo_image_surface_get_data(surface);
  const int stride = cairo_image_surface_get_stride(surface);
  for (int y = 0; y < image.height; ++y) {
    const auto* row =
        reinterpret_cast<const std::uint32_t*>(data + static_cast<std::ptrdiff_t>(y) * stride);
    for (int x = 0; x < image.width; ++x) {
      const std::uint32_t p = row[x];
      const std::uint32_t a = format == CAIRO_FORMAT_RGB24 ? 255u : p >> 24;
      const auto unpremultiply = [a](std::uint32_t v) {
        return static_cast<std::uint8_t>(a == 0 ? 0 : (v * 255 + a / 2) / a);
      };
      image.set(x, y,
                {unpremultiply((p >> 16) & 0xffu), unpremultiply((p >> 8) & 0xffu),
                 unpremultiply(p & 0xffu), static_cast<std::uint8_t>(a)});
    }
  }
  return image;
}

}  // namespace feedflow::render
