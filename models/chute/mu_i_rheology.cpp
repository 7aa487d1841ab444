#include "models/chute/mu_i_rheology.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace feedflow {
namespace {

double convention_factor(double packing, double match_angle, FroudeConvention convention) {
  if (!(packing > 0.0 && packing <= 1.0))
    throw std::invalid_argument("mu(I): solid fraction must lie in (0, 1]");
  return convention == FroudeConvention::SqrtGH ? std::sqrt(packing * std::cos(match_angle))
                                                : std::sqrt(packing);
}

void check_positive(double v, const char* what) {
  if (!(v > 0.0)) throw std::invalid_argument(std::string("mu(I): ") + what + " must be > 0");
}

}  // namespace

void check(const MuIRheology& r) {
  if (!(r.mu_s >= 0.0 && r.mu_s < r.mu_2))
    throw std::invalid_argument("mu(I) needs 0 <= mu_s < mu_2");
  check_positive(r.i0, "I0");
  check_positive(r.grain_size, "grain size");
  if (!(r.packing > 0.0 && r.packing <= 1.0))
    throw std::invalid_argument("mu(I): solid fraction must lie in (0, 1]");
}

double friction_coefficient(const MuIRheology& r, double inertial_number) {
  if (!(inertial_number >= 0.0)) throw std::invalid_argument("mu(I): I must be >= 0");
  if (inertial_number == 0.0) return r.mu_s;
  return r.mu_s + (r.mu_2 - r.mu_s) / (r.i0 / inertial_number + 1.0);
}

double bagnold_inertial_number(const MuIRheology& r, double angle) {
  check(r);
  const double t = std::tan(angle);
  if (!(t > r.mu_s && t < r.mu_2))
    throw std::invalid_argument("mu(I): no steady uniform layer unless mu_s < tan(angle) < mu_2");
  return r.i0 * (t - r.mu_s) / (r.mu_2 - t);
}

double bagnold_mean_velocity(const MuIRheology& r, double thickness, double angle) {
  if (!(thickness >= 0.0)) throw std::invalid_argument("mu(I): thickness must be >= 0");
  const double i = bagnold_inertial_number(r, angle);
  return 0.4 * i * std::sqrt(r.packing * kGravity * std::cos(angle)) * std::pow(thickness, 1.5) /
         r.grain_size;
}

double depth_averaged_inertial_number(double grain_size, double mean_velocity, double thickness) {
  check_positive(thickness, "thickness");
  return 2.5 * grain_size * std::abs(mean_velocity) / (thickness * std::sqrt(kGravity * thickness));
}

double i0_from_pouliquen(double beta, double length, double grain_size, double packing,
                         double match_angle, FroudeConvention convention) {
  check_positive(beta, "beta");
  check_positive(length, "L");
  check_positive(grain_size, "grain size");
  return 2.5 * beta * grain_size / (length * convention_factor(packing, match_angle, convention));
}

double length_from_i0(double i0, double beta, double grain_size, double packing,
                      double match_angle, FroudeConvention convention) {
  check_positive(i0, "I0");
  check_positive(beta, "beta");
  check_positive(grain_size, "grain size");
  return 2.5 * beta * grain_size / (i0 * convention_factor(packing, match_angle, convention));
}

double beta_from_i0(double i0, double length, double grain_size, double packing,
                    double match_angle, FroudeConvention convention) {
  check_positive(i0, "I0");
  check_positive(length, "L");
  check_positive(grain_size, "grain size");
  return i0 * length * convention_factor(packing, match_angle, convention) / (2.5 * grain_size);
}

MuIRheology mu_i_from_pouliquen(const PouliquenLaw& law, double grain_size, double packing,
                                double match_angle, FroudeConvention convention) {
  check(law);
  return {std::tan(law.theta1), std::tan(law.theta2),
          i0_from_pouliquen(law.beta, law.length, grain_size, packing, match_angle, convention),
          grain_size, packing};
}

}  // namespace feedflow
