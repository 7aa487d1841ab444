#include "models/hopper/hopper_geometry.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

#include "models/units/angle.hpp"

namespace feedflow {

const char* to_string(FlowGeometry g) { return g == FlowGeometry::plane ? "plane" : "conical"; }

FlowGeometry flow_geometry(const Hopper& hopper) {
  if (hopper.shape == "wedge") return FlowGeometry::plane;
  if (hopper.shape == "conical") return FlowGeometry::conical;
  throw std::invalid_argument("hopper shape must be \"wedge\" or \"conical\", got \"" +
                              hopper.shape + "\"");
}

double wall_stress_angle(double delta, double phi_w) {
  if (!(delta > 0.0 && delta < 0.5 * std::numbers::pi))
    throw std::invalid_argument("effective angle of internal friction must lie in (0, 90) deg");
  if (!(phi_w >= 0.0 && phi_w <= delta))
    throw std::invalid_argument(
        "wall friction angle must lie in [0, delta]: a wall rougher than the bulk solid "
        "shears inside the solid, not at the wall");
  return 0.5 * (phi_w + std::asin(std::sin(phi_w) / std::sin(delta)));
}

double jenike_arch_factor(FlowGeometry g, double theta) {
  if (!(theta >= 0.0 && theta < 0.5 * std::numbers::pi))
    throw std::invalid_argument("hopper semi-angle must lie in [0, 90) deg");
  const double deg = in_degrees(theta);
  return g == FlowGeometry::plane ? 1.0 + deg / 180.0 : 2.0 + deg / 60.0;
}

}  // namespace feedflow
