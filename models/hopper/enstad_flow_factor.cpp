#include "models/hopper/enstad_flow_factor.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace feedflow {
namespace {

void require_semi_angle(double theta) {
  if (!(theta > 0.0 && theta < 0.5 * std::numbers::pi))
    throw std::invalid_argument("hopper semi-angle must lie in (0, 90) deg");
}

// (1 + sin delta) Y / (X - 1): sigma1 per rho g r in the radial part of the passive field.
double radial_stress_ratio(FlowGeometry g, double theta, double delta, double phi_w) {
  const auto [x, y] = enstad_coefficients(g, theta, delta, phi_w);
  return (1.0 + std::sin(delta)) * y / (x - 1.0);
}

}  // namespace

EnstadCoefficients enstad_coefficients(FlowGeometry g, double theta, double delta,
                                       double phi_w) {
  require_semi_angle(theta);
  const double beta = wall_stress_angle(delta, phi_w);
  const int m = geometry_index(g);
  const double sd = std::sin(delta);
  const double bt = beta + theta;
  const double x = (std::pow(2.0, m) * sd / (1.0 - sd)) *
                   (std::sin(2.0 * beta + theta) / std::sin(theta) + 1.0);
  // [2(1 - cos(beta+theta))]^m (beta+theta)^(1-m): the arch-area term; m selects which factor.
  const double area_term = m == 0 ? bt : 2.0 * (1.0 - std::cos(bt));
  const double y = (area_term * std::sin(theta) + std::sin(beta) * std::pow(std::sin(bt), 1 + m)) /
                   ((1.0 - sd) * std::pow(std::sin(bt), 2 + m));
  return {x, y};
}

double enstad_flow_factor(FlowGeometry g, double theta, double delta, double phi_w) {
  const auto [x, y] = enstad_coefficients(g, theta, delta, phi_w);
  return jenike_arch_factor(g, theta) * (1.0 + std::sin(delta)) * y /
         (2.0 * (x - 1.0) * std::sin(theta));
}

double enstad_passive_major_stress(FlowGeometry g, double theta, double delta, double phi_w,
                                   double rho, double r_t, double sigma1_t, double r,
                                   double gravity) {
  if (!(rho > 0.0 && r_t > 0.0 && r > 0.0 && gravity > 0.0))
    throw std::invalid_argument("passive stress field needs positive density, radii and g");
  const double k = radial_stress_ratio(g, theta, delta, phi_w);
  const double x = enstad_coefficients(g, theta, delta, phi_w).x;
  return rho * gravity * r * k + (sigma1_t - rho * gravity * r_t * k) * std::pow(r / r_t, x);
}

std::vector<PassiveStressPoint> enstad_passive_stress_profile(
    FlowGeometry g, double theta, double delta, double phi_w, double rho, double r_o,
    double r_t, double sigma1_t, int points, double gravity) {
  if (points < 2) throw std::invalid_argument("a stress profile needs at least 2 points");
  if (!(r_o > 0.0 && r_o < r_t))
    throw std::invalid_argument("outlet radius must lie between 0 and the transition radius");
  std::vector<PassiveStressPoint> profile;
  profile.reserve(static_cast<std::size_t>(points));
  for (int i = 0; i < points; ++i) {
    const double r = r_o + (r_t - r_o) * i / (points - 1);
    profile.push_back(
        {r, enstad_passive_major_stress(g, theta, delta, phi_w, rho, r_t, sigma1_t, r, gravity)});
  }
  return profile;
}

}  // namespace feedflow
