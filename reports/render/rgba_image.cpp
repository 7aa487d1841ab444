#include "reports/render/rgba_image.hpp"

#include <cairo.h>

#include <stdexcept>
#include <string>

#include "reports/render/cairo_bridge.hpp"

namespace feedflow::render {

void write_png(const RgbaImage& image, const std::filesystem::path& file) {
  const CairoSurface surface = to_cairo_surface(image);
  const cairo_status_t status = cairo_surface_write_to_png(surface.get(), file.c_str());
  if (status != CAIRO_STATUS_SUCCESS) {
    throw std::runtime_error("cannot write PNG " + file.string() + ": " +
                             cairo_status_to_string(status));
  }
}

std::string encode_png(const RgbaImage& image) {
  const CairoSurface surface = to_cairo_surface(image);
  std::string bytes;
  const cairo_status_t status = cairo_surface_write_to_png_stream(
      surface.get(),
      [](void* closure, const unsigned char* data, unsigned int length) {
        static_cast<std::string*>(closure)->append(reinterpret_cast<const char*>(data), length);
        return CAIRO_STATUS_SUCCESS;
      },
      &bytes);
  if (status != CAIRO_STATUS_SUCCESS)
    throw std::runtime_error(std::string("cannot encode PNG: ") + cairo_status_to_string(status));
  return bytes;
}

RgbaImage read_png(const std::filesystem::path& file) {
  CairoSurface surface(cairo_image_surface_create_from_png(file.c_str()));
  const cairo_status_t status = cairo_surface_status(surface.get());
  if (status != CAIRO_STATUS_SUCCESS) {
    throw std::runtime_error("cannot read PNG " + file.string() + ": " +
                             cairo_status_to_string(status));
  }
  return from_cairo_surface(surface.get());
}

std::uint64_t pixel_checksum(const RgbaImage& image) {
  std::uint64_t h = 14695981039346656037ull;
  const auto mix = [&h](std::uint64_t byte) {
    h ^= byte;
    h *= 1099511628211ull;
  };
  for (int shift = 0; shift < 32; shift += 8) {
    mix((static_cast<std::uint32_t>(image.width) >> shift) & 0xffu);
    mix((static_cast<std::uint32_t>(image.height) >> shift) & 0xffu);
  }
  for (std::uint8_t byte : image.pixels) mix(byte);
  return h;
}

}  // namespace feedflow::render
