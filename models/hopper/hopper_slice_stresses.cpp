#include "models/hopper/hopper_slice_stresses.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace feedflow {
namespace {

void check(const HopperSlice& s) {
  if (!(s.semi_angle > 0.0 && s.semi_angle < 0.5 * std::numbers::pi))
    throw std::invalid_argument("hopper semi-angle must lie in (0, 90) deg");
  if (!(s.wall_friction_angle >= 0.0 && s.stress_ratio > 0.0 && s.bulk_density > 0.0 &&
        s.transition_height > 0.0 && s.transition_stress >= 0.0 && s.gravity > 0.0))
    throw std::invalid_argument("hopper slice needs phi_w >= 0, positive lambda_h, density, "
                                "transition height and g, and sigma_vt >= 0");
}

}  // namespace

double passive_hopper_stress_ratio(double theta, double delta, double phi_w) {
  const double beta = wall_stress_angle(delta, phi_w);
  const double sd = std::sin(delta);
  return (1.0 + sd * std::cos(2.0 * beta)) / (1.0 - sd * std::cos(2.0 * (beta + theta)));
}

double slice_exponent(const HopperSlice& s) {
  check(s);
  return (geometry_index(s.geometry) + 1) *
         (s.stress_ratio * (1.0 + std::tan(s.wall_friction_angle) / std::tan(s.semi_angle)) -
          1.0);
}

HopperStressPoint slice_stress(const HopperSlice& s, double h) {
  const double n = slice_exponent(s);
  if (!(h > 0.0 && h <= s.transition_height * (1.0 + 1e-12)))
    throw std::invalid_argument("slice height must lie in (0, transition height]");
  const double x = h / s.transition_height;
  const double rg = s.bulk_density * s.gravity;
  const double particular = std::abs(n - 1.0) < 1e-9
                                ? -rg * h * std::log(x)  // the n = 1 limit
                                : rg * h / (n - 1.0) * (1.0 - std::pow(x, n - 1.0));
  const double sv = particular + s.transition_stress * std::pow(x, n);
  const double sn = s.stress_ratio * sv;
  return {h, sv, sn, std::tan(s.wall_friction_angle) * sn};
}

std::vector<HopperStressPoint> hopper_slice_profile(const HopperSlice& s, double h_o,
                                                    int points) {
  if (points < 2) throw std::invalid_argument("a stress profile needs at least 2 points");
  if (!(h_o > 0.0 && h_o < s.transition_height))
    throw std::invalid_argument("outlet height must lie between the apex and the transition");
  std::vector<HopperStressPoint> profile;
  profile.reserve(static_cast<std::size_t>(points));
  for (int i = 0; i < points; ++i)
    profile.push_back(
        slice_stress(s, s.transition_height - (s.transition_height - h_o) * i / (points - 1)));
  return profile;
}

std::vector<HopperStressPoint> emptying_silo_profile(const Hopper& hopper, double rho,
                                                     double delta, double phi_w,
                                                     StressRatioRule rule, int points,
                                                     double gravity) {
  const FlowGeometry g = flow_geometry(hopper);
  const double h_t = hopper.transition_height();
  const double h_o = hopper.outlet_height();
  if (!(h_o < h_t)) throw std::invalid_argument("outlet must be narrower than the bin");
  std::vector<HopperStressPoint> profile;
  double sigma_vt = 0.0;
  if (hopper.fill_height > h_t) {
    const JanssenBin bin{g == FlowGeometry::plane
                             ? plane_bin_hydraulic_radius(hopper.bin_width, hopper.slot_length)
                             : round_bin_hydraulic_radius(hopper.bin_width),
                         rho, janssen_stress_ratio(rule, delta), std::tan(phi_w), 0.0, gravity};
    for (const auto& p : janssen_profile(bin, hopper.fill_height - h_t, points))
      profile.push_back({hopper.fill_height - p.depth, p.vertical, p.wall_normal, p.wall_shear});
    sigma_vt = profile.back().vertical;
  }
  const HopperSlice slice{g,   hopper.semi_angle, phi_w, passive_hopper_stress_ratio(hopper.semi_angle, delta, phi_w),
                          rho, std::min(h_t, hopper.fill_height), sigma_vt, gravity};
  for (const auto& p : hopper_slice_profile(slice, h_o, points)) profile.push_back(p);
  return profile;
}

}  // namespace feedflow
