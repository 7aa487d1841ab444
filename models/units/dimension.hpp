#pragma once
// Physical dimension as integer exponents of length, mass, time and plane angle.
// Angle is kept as its own base dimension (unlike strict SI) so that "30 mm" given for an angle,
// or "20 Hz" for a drum speed in rpm, is caught as a mismatch instead of passing silently.
#include <compare>
#include <string>

namespace feedflow {

struct Dimension {
  int length = 0;
  int mass = 0;
  int time = 0;
  int angle = 0;

  friend constexpr bool operator==(const Dimension&, const Dimension&) = default;
  constexpr Dimension operator*(const Dimension& o) const {
    return {length + o.length, mass + o.mass, time + o.time, angle + o.angle};
  }
  constexpr Dimension operator/(const Dimension& o) const {
    return {length - o.length, mass - o.mass, time - o.time, angle - o.angle};
  }
  constexpr Dimension pow(int k) const { return {length * k, mass * k, time * k, angle * k}; }
};

namespace dim {
inline constexpr Dimension dimensionless{};
inline constexpr Dimension length{1, 0, 0, 0};
inline constexpr Dimension mass{0, 1, 0, 0};
inline constexpr Dimension time{0, 0, 1, 0};
inline constexpr Dimension angle{0, 0, 0, 1};
inline constexpr Dimension area = length.pow(2);
inline constexpr Dimension volume = length.pow(3);
inline constexpr Dimension velocity = length / time;
inline constexpr Dimension acceleration = velocity / time;
inline constexpr Dimension angular_speed = angle / time;
inline constexpr Dimension rate = Dimension{} / time;
inline constexpr Dimension density = mass / volume;
inline constexpr Dimension mass_flow_rate = mass / time;
inline constexpr Dimension force = mass * acceleration;
inline constexpr Dimension pressure = force / area;
inline constexpr Dimension energy = force * length;
inline constexpr Dimension viscosity = pressure * time;
}  // namespace dim

// A human name for a dimension ("length", "angle", "density", ...), or its SI unit when it has
// no common name.
std::string dimension_name(const Dimension& d);

// The SI unit of a dimension, written as feedflow parses it ("m", "kg/m^3", "rad/s", ...).
std::string si_unit(const Dimension& d);

// An example of a valid value for a dimension, for error messages ("30 deg", "60 mm").
std::string example_value(const Dimension& d);

}  // namespace feedflow
