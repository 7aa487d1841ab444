#pragma once
// How a sphere is lit: a fixed light above-left and in front of the viewer (camera space:
// x right, y up, z toward the viewer), Lambert diffuse plus a Blinn-Phong highlight. The
// impostor fragment shader uses these numbers; `shade` is the same formula on the CPU, so a test
// can predict a pixel.
#include <algorithm>
#include <cmath>

#include "reports/render/colour_map.hpp"
#include "reports/render/vec3.hpp"

namespace feedflow::render {

struct SphereShading {
  static constexpr double ambient = 0.35;
  static constexpr double diffuse = 0.65;
  static constexpr double specular = 0.25;
  static constexpr double shininess = 32.0;
  static Vec3 light() { return normalised(Vec3{-0.35, 0.45, 0.82}); }
  static Vec3 half_vector() { return normalised(light() + Vec3{0.0, 0.0, 1.0}); }
};

// The colour of a sphere of base colour `base` where its unit normal (camera space) is `n`.
inline Rgb8 shade(Rgb8 base, Vec3 n) {
  const double lambert = std::max(dot(n, SphereShading::light()), 0.0);
  const double highlight =
      SphereShading::specular *
      std::pow(std::max(dot(n, SphereShading::half_vector()), 0.0), SphereShading::shininess);
  const double k = SphereShading::ambient + SphereShading::diffuse * lambert;
  const auto channel = [&](std::uint8_t c) {
    const double v = std::min(1.0, c / 255.0 * k + highlight);
    return static_cast<std::uint8_t>(std::lround(255.0 * v));
  };
  return {channel(base.r), channel(base.g), channel(base.b)};
}

}  // namespace feedflow::render
