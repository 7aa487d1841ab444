#pragma once
// Colour maps and the colour scale of a snapshot: a sequential map (viridis: perceptually
// uniform, readable in grey and by colour-blind readers) for speed, pressure or any field, and a
// qualitative map for integer ids such as the initial layer of a particle.
#include <cstdint>
#include <string>

namespace feedflow::render {

struct Rgb8 {
  std::uint8_t r = 0;
  std::uint8_t g = 0;
  std::uint8_t b = 0;
  friend bool operator==(Rgb8, Rgb8) = default;
};

// Viridis at t in [0, 1] (clamped; NaN gives the t = 0 end), linear between nine stops.
Rgb8 viridis(double t);

// The qualitative colour of an integer id; ten distinct hues, repeating. Negative ids are grey.
Rgb8 layer_colour(std::int32_t layer);

// How per-particle or per-cell scalars map to colours: `lo` maps to viridis(0), `hi` to
// viridis(1); values outside are clamped. `quantity` and `unit` label the colour bar
// ("speed", "m/s").
struct ColourScale {
  std::string quantity;
  std::string unit;
  double lo = 0.0;
  double hi = 1.0;

  // (v - lo) / (hi - lo) clamped to [0, 1]; 0.5 when lo == hi.
  double fraction(double v) const;
  Rgb8 colour(double v) const { return viridis(fraction(v)); }
};

}  // namespace feedflow::render
