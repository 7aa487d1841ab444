#include "fullsim/dem/scene/sawtooth_ramp.hpp"

#include <cmath>

namespace feedflow {

void add_slab_strip(TriangleMesh& m, const Vec3& a, const Vec3& b, double depth, std::size_t& n) {
  const Vec3 y0(0.0, -depth, 0.0), y1(0.0, 2.0 * depth, 0.0);
  m.add_triangle(a + y0, b + y0, b + y1, n++);
  m.add_triangle(a + y0, b + y1, a + y1, n++);
}

TriangleMesh sawtooth_ramp(double from, double to, double radius, double depth) {
  const double period = 2.0 * radius, h = radius;
  TriangleMesh ramp;
  ramp.source = "saw-tooth ramp (45 deg faces, period 2R, height R)";
  std::size_t n = 0;
  const long teeth = static_cast<long>(std::ceil((to - from) / period - 1e-9));
  for (long k = 0; k < teeth; ++k) {
    const double x = from + k * period;
    add_slab_strip(ramp, Vec3(x, 0, 0), Vec3(x + 0.5 * period, 0, h), depth, n);
    add_slab_strip(ramp, Vec3(x + 0.5 * period, 0, h), Vec3(x + period, 0, 0), depth, n);
  }
  return ramp;
}

}  // namespace feedflow
