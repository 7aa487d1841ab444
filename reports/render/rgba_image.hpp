#pragma once
// An 8-bit RGBA image in memory (rows top to bottom, straight alpha) and its PNG file.
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace feedflow::render {

struct Rgba8 {
  std::uint8_t r = 0;
  std::uint8_t g = 0;
  std::uint8_t b = 0;
  std::uint8_t a = 0;
  friend bool operator==(Rgba8, Rgba8) = default;
};

struct RgbaImage {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> pixels;  // 4 bytes per pixel, row y at offset 4 * width * y

  RgbaImage() = default;
  RgbaImage(int w, int h) : width(w), height(h), pixels(4 * static_cast<std::size_t>(w) * h) {}

  Rgba8 at(int x, int y) const {
    const std::size_t k = 4 * (static_cast<std::size_t>(y) * width + x);
    return {pixels[k], pixels[k + 1], pixels[k + 2], pixels[k + 3]};
  }
  void set(int x, int y, Rgba8 c) {
    const std::size_t k = 4 * (static_cast<std::size_t>(y) * width + x);
    pixels[k] = c.r;
    pixels[k + 1] = c.g;
    pixels[k + 2] = c.b;
    pixels[k + 3] = c.a;
  }
};

// Writes `image` as a PNG (through cairo). Throws std::runtime_error naming the file on failure.
void write_png(const RgbaImage& image, const std::filesystem::path& file);

// The PNG bytes of `image` (for embedding in reports). Throws std::runtime_error on failure.
std::string encode_png(const RgbaImage& image);
// Reads a PNG back. Throws std::runtime_error naming the file when it is missing or not a PNG.
RgbaImage read_png(const std::filesystem::path& file);

// A 64-bit FNV-1a hash of the size and the pixels, to compare renders cheaply.
std::uint64_t pixel_checksum(const RgbaImage& image);

}  // namespace feedflow::render
