#include "models/hopper/minimum_energy_discharge.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>

#include "models/numerics/adaptive_integral.hpp"
#include "models/numerics/brent_root.hpp"

namespace feedflow {

MinimumEnergyDischarge brown_richards_wedge(double theta) {
  if (!(theta > 0.0 && theta <= 0.5 * std::numbers::pi))
    throw std::invalid_argument("Brown-Richards semi-angle must lie in (0, 90] deg");
  const auto energy_balance = [theta](double e) {
    return adaptive_integral(
        [e](double phi) { return (2.0 * e - 3.0 * std::cos(phi)) / std::sqrt(e - std::cos(phi)); },
        0.0, theta, 1e-12, 1e-10, "Brown-Richards energy integral");
  };
  // The integrand rises with e, the integral goes to -infinity as e -> 1+ and is positive for
  // e >= 3/2: a single root in (1, 3/2] (above 1.1 for any semi-angle up to 90 deg).
  const double e = brent_root(energy_balance, 1.0 + 1e-6, 1.5, 1e-13, 1e-13,
                              "Brown-Richards energy constant");
  const double flux = adaptive_integral(
      [e](double phi) { return std::sqrt(2.0 * (e - std::cos(phi))); }, 0.0, theta, 0.0,
      1e-10, "Brown-Richards flux integral");
  // r0^(3/2) / B^(3/2) = (2 sin theta)^(-3/2).
  return {2.0 * flux / std::pow(2.0 * std::sin(theta), 1.5), e};
}

double brown_richards_rate_per_metre(double rho, double b, double theta, double gravity) {
  if (!(rho > 0.0 && b > 0.0 && gravity > 0.0))
    throw std::invalid_argument("Brown-Richards rate needs positive density, width and g");
  return brown_richards_wedge(theta).coefficient * rho * std::sqrt(gravity) * std::pow(b, 1.5);
}

}  // namespace feedflow
