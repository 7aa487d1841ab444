#include "models/hopper/discharge_rate.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

#include "models/core/errors.hpp"
#include "models/numerics/brent_root.hpp"

namespace feedflow {
namespace {

constexpr double kPi = std::numbers::pi;

void require_angle(double theta) {
  if (!(theta > 0.0 && theta < 0.5 * kPi))
    throw std::invalid_argument("hopper semi-angle must lie in (0, 90) deg");
}

void require_positive(double v, const char* what) {
  if (!(v > 0.0) || !std::isfinite(v))
    throw std::invalid_argument(std::string(what) + " must be a positive number");
}

// Outlet area per metre of slot (plane) or of the circle (conical) [m or m^2].
double outlet_area(FlowGeometry g, double b) {
  return g == FlowGeometry::plane ? b : 0.25 * kPi * b * b;
}

double effective_width(double b, double k, double d) {
  require_positive(b, "outlet width");
  if (!(d >= 0.0 && k >= 0.0)) throw std::invalid_argument("k and d must be >= 0");
  if (b <= k * d)
    throw std::invalid_argument("Beverloo needs an outlet wider than k d (it is meant for "
                                "B >= 6 d)");
  return b - k * d;
}

}  // namespace

JohansonDischarge johanson_discharge(FlowGeometry g, double theta, double b, double ff,
                                     const FlowFunction& f, const BulkDensity& density,
                                     double gravity) {
  require_angle(theta);
  require_positive(b, "outlet width");
  require_positive(ff, "flow factor");
  require_positive(gravity, "gravity");
  const double h = jenike_arch_factor(g, theta);
  // rho_b at the outlet stress, which itself scales with rho_b: fixed-point iteration.
  double rho = density.at(0.0), sigma1 = 0.0;
  for (int iter = 0;; ++iter) {
    sigma1 = ff * rho * gravity * b / h;
    const double next = density.at(sigma1);
    if (std::abs(next - rho) <= 1e-12 * rho) break;
    rho = next;
    if (iter == 100)
      throw NumericalFailure("Johanson discharge: outlet bulk density did not settle in 100 "
                             "iterations (rho_b(sigma1) too steep?)");
  }
  const double strength = f.unconfined_yield_strength(sigma1);
  const double ff_a =
      strength > 0.0 ? sigma1 / strength : std::numeric_limits<double>::infinity();
  const double factor = std::max(0.0, 1.0 - ff / ff_a);
  const int m = geometry_index(g);
  const double v0 = std::sqrt(b * gravity * factor / (2.0 * (1 + m) * std::tan(theta)));
  return {rho * outlet_area(g, b) * v0, v0, factor, ff_a, sigma1, rho};
}

double beverloo_circular_rate(double rho, double diameter, double d, double k, double c,
                              double gravity) {
  require_positive(rho, "bulk density");
  return c * rho * std::sqrt(gravity) * std::pow(effective_width(diameter, k, d), 2.5);
}

double beverloo_slot_rate_per_metre(double rho, double b, double d, double k, double c2,
                                    double gravity) {
  require_positive(rho, "bulk density");
  return c2 * rho * std::sqrt(gravity) * std::pow(effective_width(b, k, d), 1.5);
}

double beverloo_slot_rate(double rho, double b, double slot_length, double d, double k,
                          double c2, double gravity) {
  return beverloo_slot_rate_per_metre(rho, b, d, k, c2, gravity) *
         effective_width(slot_length, k, d);
}

double rose_tanaka_factor(double theta, double phi_d) {
  require_angle(theta);
  require_angle(phi_d);
  return theta < 0.5 * kPi - phi_d ? std::pow(std::tan(theta) * std::tan(phi_d), -0.35) : 1.0;
}

double hourglass_rate(FlowGeometry g, double rho, double b, double theta, double phi,
                      double r1, double gravity) {
  require_angle(theta);
  require_positive(rho, "bulk density");
  require_positive(b, "outlet width");
  if (!(phi > 0.0 && phi < 0.5 * kPi))
    throw std::invalid_argument("internal friction angle must lie in (0, 90) deg");
  const int m = geometry_index(g);
  const double k = (1.0 + std::sin(phi)) / (1.0 - std::sin(phi));
  const double n = (1 + m) * (k - 1.0);
  if (!(n > 1.0))
    throw std::invalid_argument(
        "hourglass theory needs (1+m)(k-1) > 1: phi > 19.5 deg plane, > 9.6 deg conical");
  const double r0 = 0.5 * b / std::sin(theta);
  if (!(r1 > r0)) throw std::invalid_argument("top radius must lie above the outlet arc");
  const double ratio = r0 / r1;  // 0 for an infinitely tall hopper
  const double v2 = gravity * r0 * (n + 2 * m + 2) / ((1 + m) * (n - 1)) *
                    (1.0 - std::pow(ratio, n - 1)) / (1.0 - std::pow(ratio, n + 2 * m + 2));
  const double v = std::sqrt(v2);
  return g == FlowGeometry::plane ? rho * 2.0 * theta * r0 * v
                                  : rho * 2.0 * kPi * r0 * r0 * (1.0 - std::cos(theta)) * v;
}

double carleton_outlet_velocity(FlowGeometry g, double theta, double b, const AirDrag& air,
                                double gravity) {
  require_angle(theta);
  require_positive(b, "outlet width");
  require_positive(air.particle_density, "particle density");
  require_positive(air.particle_size, "particle size");
  if (!(air.fluid_density >= 0.0 && air.fluid_viscosity >= 0.0))
    throw std::invalid_argument("fluid density and viscosity must be >= 0");
  const double inertia = 2.0 * (1 + geometry_index(g)) * std::sin(theta) / b;
  const double drag = 15.0 * std::cbrt(air.fluid_density) *
                      std::pow(air.fluid_viscosity, 2.0 / 3.0) /
                      (air.particle_density * std::pow(air.particle_size, 5.0 / 3.0));
  const double v_free = std::sqrt(gravity / inertia);
  if (drag == 0.0) return v_free;
  const auto balance = [&](double v) {
    return inertia * v * v + drag * std::pow(v, 4.0 / 3.0) - gravity;
  };
  // balance(0) = -g < 0 and balance(v_free) = drag v_free^(4/3) > 0: one root between.
  return brent_root(balance, 0.0, v_free, 1e-14, 1e-12, "Carleton outlet velocity");
}

double air_drag_factor(FlowGeometry g, double theta, double b, const AirDrag& air,
                       double gravity) {
  AirDrag still = air;
  still.fluid_density = 0.0;
  still.fluid_viscosity = 0.0;
  return carleton_outlet_velocity(g, theta, b, air, gravity) /
         carleton_outlet_velocity(g, theta, b, still, gravity);
}

double slot_rate(double rate_per_metre, double slot_length) {
  require_positive(slot_length, "slot length");
  if (!(rate_per_metre >= 0.0)) throw std::invalid_argument("rate must be >= 0");
  return rate_per_metre * slot_length;
}

}  // namespace feedflow
