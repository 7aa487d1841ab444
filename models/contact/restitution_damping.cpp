#include "models/contact/restitution_damping.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace feedflow {

double restitution_beta(double restitution) {
  if (restitution >= 1.0) return 0.0;
  if (restitution <= 0.0) return -1.0;
  const double l = std::log(restitution);
  return l / std::sqrt(l * l + std::numbers::pi * std::numbers::pi);
}

double linear_damping_factor(double restitution) {
  const double b = restitution_beta(restitution);
  return b * b;
}

namespace {

// Unit system: m* = 1, (4/3) E* sqrt(R*) = 1, impact speed 1, so the elastic force is x^1.5
// and S_n = 1.5 sqrt(x); the damping force is c sqrt(1.5) x^0.25 xdot. RK4 on (x, xdot),
// 4000 steps over the elastic contact time 3.2 (the damped one is shorter), the exit crossing
// interpolated linearly.
double impact_rebound(double c) {
  const double g = c * std::sqrt(1.5);
  auto accel = [g](double x, double v) {
    if (x <= 0.0) return 0.0;
    const double f = x * std::sqrt(x) + g * std::sqrt(std::sqrt(x)) * v;
    return -std::max(f, 0.0);  // force clipped at zero, as the law does
  };
  const double h = 3.3 / 4000.0;
  double x = 0.0, v = 1.0;
  for (int i = 0; i < 400000; ++i) {
    const double k1x = v, k1v = accel(x, v);
    const double k2x = v + 0.5 * h * k1v, k2v = accel(x + 0.5 * h * k1x, v + 0.5 * h * k1v);
    const double k3x = v + 0.5 * h * k2v, k3v = accel(x + 0.5 * h * k2x, v + 0.5 * h * k2v);
    const double k4x = v + h * k3v, k4v = accel(x + h * k3x, v + h * k3v);
    const double xn = x + h / 6.0 * (k1x + 2 * k2x + 2 * k3x + k4x);
    const double vn = v + h / 6.0 * (k1v + 2 * k2v + 2 * k3v + k4v);
    if (i > 0 && xn <= 0.0) return -vn;  // after exit the velocity no longer changes
    x = xn;
    v = vn;
  }
  return 0.0;
}

}  // namespace

double hertz_restitution(double coefficient) { return impact_rebound(coefficient); }

double hertz_damping_coefficient(double restitution, HertzDampingForm form) {
  if (form == HertzDampingForm::liggghts)
    return -2.0 * std::sqrt(5.0 / 6.0) * restitution_beta(restitution);
  if (restitution >= 1.0) return 0.0;
  double lo = 0.0, hi = 1.0;
  while (impact_rebound(hi) > std::max(restitution, 0.0) && hi < 1e3) hi *= 2.0;
  for (int i = 0; i < 50; ++i) {
    const double mid = 0.5 * (lo + hi);
    (impact_rebound(mid) > restitution ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

}  // namespace feedflow
