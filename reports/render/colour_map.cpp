#include "reports/render/colour_map.hpp"

#include <array>
#include <cmath>

namespace feedflow::render {

namespace {

// Viridis sampled at nine equally spaced stops (van der Walt and Smith's map as published).
constexpr std::array<Rgb8, 9> kViridisStops{{{68, 1, 84},
                                             {71, 45, 123},
                                             {59, 82, 139},
                                             {44, 114, 142},
                                             {33, 145, 140},
                                             {40, 174, 128},
                                             {94, 201, 98},
                                             {173, 220, 48},
                                             {253, 231, 37}}};

// Ten hues that stay distinct next to each other; the first four also survive greyscale print.
constexpr std::array<Rgb8, 10> kLayerColours{{{31, 119, 180},
                                              {255, 127, 14},
                                              {44, 160, 44},
                                              {214, 39, 40},
                                              {148, 103, 189},
                                              {140, 86, 75},
                                              {227, 119, 194},
                                              {188, 189, 34},
                                              {23, 190, 207},
                                              {96, 96, 96}}};

std::uint8_t mix(std::uint8_t a, std::uint8_t b, double s) {
  return static_cast<std::uint8_t>(std::lround(a + s * (static_cast<double>(b) - a)));
}

}  // namespace

Rgb8 viridis(double t) {
  if (!(t > 0.0)) return kViridisStops.front();
  if (t >= 1.0) return kViridisStops.back();
  const double position = t * (kViridisStops.size() - 1);
  const auto k = static_cast<std::size_t>(position);
  const double s = position - static_cast<double>(k);
  const Rgb8 a = kViridisStops[k];
  const Rgb8 b = kViridisStops[k + 1];
  return {mix(a.r, b.r, s), mix(a.g, b.g, s), mix(a.b, b.b, s)};
}

Rgb8 layer_colour(std::int32_t layer) {
  if (layer < 0) return {160, 160, 160};
  return kLayerColours[static_cast<std::size_t>(layer) % kLayerColours.size()];
}

double ColourScale::fraction(double v) const {
  if (!(hi > lo)) return 0.5;
  const double t = (v - lo) / (hi - lo);
  if (!(t > 0.0)) return 0.0;
  return t < 1.0 ? t : 1.0;
}

}  // namespace feedflow::render
