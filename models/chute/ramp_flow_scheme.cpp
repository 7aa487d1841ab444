#include "models/chute/ramp_flow_scheme.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>


namespace feedflow {

RampFlowScheme::RampFlowScheme(RampGrid grid, RampPhysics physics)
    : grid_(grid),
      physics_(physics),
      friction_(physics.friction),
      rest_(grid.cells, 1),
      friction_start_(grid.cells, 0.0),
      u_(grid.cells, 0.0) {
  if (grid_.cells < 2 || !(grid_.x_end > grid_.x_begin))
    throw std::invalid_argument("ramp flow: need at least 2 cells on a domain of positive length");
  const auto& law = physics_.friction;
  if (!(physics_.angle >= 0.0 && physics_.angle < std::numbers::pi / 2))
    throw std::invalid_argument("ramp flow: angle must lie in [0, 90) degrees");
  if (!(law.theta1 >= 0.0 && law.theta1 <= law.theta2 && law.theta2 < std::numbers::pi / 2))
    throw std::invalid_argument("ramp flow: friction needs 0 <= theta1 <= theta2 < 90 degrees");
  if (law.theta1 < law.theta2 && !(law.length > 0.0 && law.beta > 0.0 && law.gamma >= 0.0))
    throw std::invalid_argument("ramp flow: Pouliquen friction needs L > 0, beta > 0, Gamma >= 0");
  if (!(physics_.earth_pressure > 0.0))
    throw std::invalid_argument("ramp flow: earth-pressure coefficient must be > 0");
  if ((physics_.upstream == RampBoundary::Periodic) != (physics_.downstream == RampBoundary::Periodic))
    throw std::invalid_argument("ramp flow: periodic boundaries come in pairs");
  if (physics_.upstream == RampBoundary::Outflow)
    throw std::invalid_argument("ramp flow: the upstream end is a wall (or periodic)");
  if (physics_.gate_face && (*physics_.gate_face == 0 || *physics_.gate_face >= grid_.cells))
    throw std::invalid_argument("ramp flow: the gate must sit on an interior face");
  if (physics_.gate_face && !(physics_.gate_opening > 0.0))
    throw std::invalid_argument("ramp flow: gate opening must be > 0");
  gk_ = physics_.earth_pressure * kGravity * std::cos(physics_.angle);
  dz_ = -grid_.dx() * std::tan(physics_.angle) / physics_.earth_pressure;
  rec_.resize(grid_.cells);
}

void RampFlowScheme::begin_step(const double* state) {
  const std::size_t n = grid_.cells;
  const double g_cos = kGravity * std::cos(physics_.angle);
  for (std::size_t i = 0; i < n; ++i) {
    const double h = state[i], q = state[n + i];
    rest_[i] = q == 0.0;
    friction_start_[i] = 0.0;
    if (q != 0.0 && h > physics_.dry_thickness) {
      const double froude = std::abs(q) / (h * std::sqrt(kGravity * h));
      friction_start_[i] = std::copysign(friction_.coefficient(h, froude) * g_cos * h, q);
    }
  }
}

double RampFlowScheme::velocity(double h, double q) const {
  return h > physics_.dry_thickness ? q / h : 0.0;
}

void RampFlowScheme::cap_at_gate(std::size_t face, Star& s) const {
  if (physics_.gate_face && *physics_.gate_face == face) {
    s.left = std::min(s.left, physics_.gate_opening);
    s.right = std::min(s.right, physics_.gate_opening);
  }
}

RampFlowScheme::Star RampFlowScheme::resting_pair(std::size_t face, double hl, double hr) const {
  double dz = dz_;
  if (hl > physics_.dry_thickness || hr > physics_.dry_thickness) {
    const double mu = friction_.at_rest(0.5 * (hl + hr));
    const double cap = mu * grid_.dx() / physics_.earth_pressure;
    dz += std::clamp(-((hr - hl) + dz_), -cap, cap);
  }
  Star s{std::max(0.0, hl - std::max(0.0, dz)), std::max(0.0, hr - std::max(0.0, -dz))};
  cap_at_gate(face, s);
  return s;
}

bool RampFlowScheme::rhs(const double* y, double* dy) {
  const std::size_t n = grid_.cells;
  const double* h = y;
  const double* q = y + n;
  double* dh = dy;
  double* dq = dy + n;
  std::fill(dy, dy + state_size(), 0.0);
  for (std::size_t i = 0; i < n; ++i) u_[i] = velocity(h[i], q[i]);
  rec_.build(physics_, dz_, h, u_.data(), n);

  // Centred bed source of each cell, k g cos (h_L + h_R)/2 (z_L - z_R) with (h_L + h_R)/2 = h_i:
  // g sin(theta) h_i dx on the exact bed.
  for (std::size_t i = 0; i < n; ++i) dq[i] -= gk_ * h[i] * (dz_ + 2.0 * rec_.bed_right[i]);

  // One face between cell l (left state: its right face) and the right state (hr, ur, bed
  // offset zr); r == n marks the outflow ghost. Returns the mass flux.
  auto face_flux = [&](std::size_t l, std::size_t r, std::size_t face, double hr, double ur,
                       double zr, bool resting, double& fq) {
    const double hl = rec_.h_right[l], ul = rec_.u_right[l], zl = rec_.bed_right[l];
    const double zs = std::max(zl, zr);
    Star s{std::max(0.0, hl + zl - zs), std::max(0.0, hr + zr - zs)};
    cap_at_gate(face, s);
    // mass between cells at rest: cell averages with the friction at rest as topography
    const double hr_cell = r < n ? h[r] : h[l];
    const double ur_cell = r < n ? u_[r] : std::max(0.0, u_[l]);
    const Star m = resting ? resting_pair(face, h[l], hr_cell) : s;
    const double uml = resting ? u_[l] : ul, umr = resting ? ur_cell : ur;
    const double a = std::max(std::abs(ul) + std::sqrt(gk_ * std::max(s.left, m.left)),
                              std::abs(ur) + std::sqrt(gk_ * std::max(s.right, m.right)));
    fq = 0.5 * (s.left * ul * ul + pressure(s.left) + s.right * ur * ur + pressure(s.right)) -
         0.5 * a * (s.right * ur - s.left * ul);
    dq[l] -= fq + pressure(hl) - pressure(s.left);
    if (r < n) dq[r] += fq + pressure(hr) - pressure(s.right);
    return 0.5 * (m.left * uml + m.right * umr) - 0.5 * a * (m.right - m.left);
  };
  auto interior = [&](std::size_t l, std::size_t r, std::size_t face) {
    double fq = 0.0;
    const double fh = face_flux(l, r, face, rec_.h_left[r], rec_.u_left[r],
                                -rec_.bed_right[r], rest_[l] && rest_[r], fq);
    dh[l] -= fh;
    dh[r] += fh;
  };
  // A closed end: the ghost mirrors the cell (same thickness and bed, opposite velocity); the
  // mass flux is exactly zero and the momentum flux is that of the mirrored Rusanov problem.
  auto wall_flux = [&](double s, double u_outward) {
    const double a = std::abs(u_outward) + std::sqrt(gk_ * s);
    return s * u_outward * u_outward + pressure(s) + a * s * u_outward;
  };

  for (std::size_t f = 1; f < n; ++f) interior(f - 1, f, f);
  if (physics_.upstream == RampBoundary::Periodic) {
    interior(n - 1, 0, n);
  } else {
    dq[0] += wall_flux(rec_.h_left[0], -rec_.u_left[0]);
    const std::size_t l = n - 1;
    bool closed = physics_.downstream == RampBoundary::Wall;
    if (!closed) {
      // Free end: a ghost continues the ramp with the last cell's thickness and no backward
      // velocity, so a layer leaves as if the ramp went on; nothing ever enters.
      const double dq_before = dq[l];
      double fq = 0.0;
      const double fh = face_flux(l, n, n, h[l], std::max(0.0, u_[l]), 0.0, rest_[l], fq);
      if (fh >= 0.0) {
        dh[l] -= fh;
        dy[2 * n] += fh;
      } else {
        dq[l] = dq_before;
        closed = true;
      }
    }
    if (closed) dq[l] -= wall_flux(rec_.h_right[l], rec_.u_right[l]);
  }
  const double inv_dx = 1.0 / grid_.dx();
  for (std::size_t i = 0; i < 2 * n; ++i) {
    dy[i] *= inv_dx;
    if (!std::isfinite(dy[i])) {
      failed_cell_ = i % n;
      return false;
    }
  }
  return std::isfinite(dy[2 * n]);
}

void RampFlowScheme::apply_friction(double* y, double dt) const {
  const std::size_t n = grid_.cells;
  const double impulse_per_mu = dt * kGravity * std::cos(physics_.angle);
  for (std::size_t i = 0; i < n; ++i) {
    const double h = y[i];
    double& q = y[n + i];
    if (h <= physics_.dry_thickness) {
      q = 0.0;
      continue;
    }
    const double speed = friction_.speed_after(h, std::abs(q) / h, impulse_per_mu);
    q = speed == 0.0 ? 0.0 : std::copysign(speed * h, q);
  }
}

void RampFlowScheme::end_step(double* y, double dt) const {
  const std::size_t n = grid_.cells;
  const double impulse_per_mu = dt * kGravity * std::cos(physics_.angle);
  for (std::size_t i = 0; i < n; ++i) {
    const double h = y[i];
    double& q = y[n + i];
    if (h <= physics_.dry_thickness) {
      q = 0.0;
      continue;
    }
    double k = impulse_per_mu;
    if (!rest_[i]) {
      q -= 0.5 * dt * friction_start_[i];
      k *= 0.5;
    }
    const double speed = friction_.speed_after(h, std::abs(q) / h, k);
    q = speed == 0.0 ? 0.0 : std::copysign(speed * h, q);
  }
}

double RampFlowScheme::max_wave_speed(const double* y) const {
  // face thicknesses reach at most the largest neighbour plus dx tan(theta)/(2k)
  const std::size_t n = grid_.cells;
  const double rise = 0.5 * std::abs(dz_);
  double a = 0.0;
  for (std::size_t i = 0; i < n; ++i)
    a = std::max(a, std::abs(velocity(y[i], y[n + i])) +
                        std::sqrt(gk_ * (std::max(0.0, y[i]) + rise)));
  return a;
}

}  // namespace feedflow
