#include "models/chute/ramp_reconstruction.hpp"

#include <algorithm>
#include <cmath>

namespace feedflow {
namespace {

// Van Leer's harmonic limiter of the two one-sided differences: smooth away from extrema,
// |slope| <= 2 min(|a|, |b|) (TVD, so face values stay between the neighbours').
double van_leer(double a, double b) {
  if (a * b <= 0.0) return 0.0;
  return 2.0 * a * b / (a + b);
}

double minmod(double a, double b) {
  if (a * b <= 0.0) return 0.0;
  return std::abs(a) < std::abs(b) ? a : b;
}

struct Neighbour {
  double h, u;
  double bed_step;  // z_(downstream) - z_(upstream) of the pair: the ramp's step, 0 for a mirror
};

}  // namespace

void RampReconstruction::resize(std::size_t n) {
  h_left.assign(n, 0.0);
  h_right.assign(n, 0.0);
  u_left.assign(n, 0.0);
  u_right.assign(n, 0.0);
  bed_right.assign(n, 0.0);
}

void RampReconstruction::build(const RampPhysics& physics, double bed_step, const double* h,
                               const double* u, std::size_t n) {
  if (h_left.size() != n) resize(n);
  fallback_cells = 0;
  const bool periodic = physics.upstream == RampBoundary::Periodic;
  auto left_of = [&](std::size_t i) -> Neighbour {
    if (i > 0) return {h[i - 1], u[i - 1], bed_step};
    if (periodic) return {h[n - 1], u[n - 1], bed_step};
    return {h[0], -u[0], 0.0};  // upstream wall: mirror
  };
  auto right_of = [&](std::size_t i) -> Neighbour {
    if (i + 1 < n) return {h[i + 1], u[i + 1], bed_step};
    if (periodic) return {h[0], u[0], bed_step};
    if (physics.downstream == RampBoundary::Wall) return {h[i], -u[i], 0.0};
    return {h[i], std::max(0.0, u[i]), bed_step};  // outflow: the ramp goes on
  };
  for (std::size_t i = 0; i < n; ++i) {
    const Neighbour l = left_of(i), r = right_of(i);
    const double dh_l = h[i] - l.h, dh_r = r.h - h[i];
    // surface differences: eta_i - eta_(i-1) = dh + (z_i - z_(i-1))
    const double deta = van_leer(dh_l + l.bed_step, dh_r + r.bed_step);
    const double du = van_leer(u[i] - l.u, r.u - u[i]);
    u_left[i] = u[i] - 0.5 * du;
    u_right[i] = u[i] + 0.5 * du;
    // h on the exact bed: h_R = eta_R - z_R = h_i + (deta - bed_step)/2
    const double half = 0.5 * (deta - bed_step);
    if (h[i] - std::abs(half) >= 0.0) {
      h_left[i] = h[i] - half;
      h_right[i] = h[i] + half;
      bed_right[i] = 0.0;
    } else {
      ++fallback_cells;
      const double dh = minmod(dh_l, dh_r);
      h_left[i] = h[i] - 0.5 * dh;
      h_right[i] = h[i] + 0.5 * dh;
      // z_R = eta_R - h_R = z_i + (deta - dh)/2, against the exact z_i + bed_step/2
      bed_right[i] = 0.5 * (deta - dh - bed_step);
    }
  }
}

}  // namespace feedflow
