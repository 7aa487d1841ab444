#include "models/chute/ramp_flow_scheme.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace feedflow {

RampFlowScheme::RampFlowScheme(RampGrid grid, RampPhysics physics)
    : grid_(grid), physics_(physics), rest_(grid.cells, 1) {
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
}

void RampFlowScheme::begin_step(const double* state) {
  for (std::size_t i = 0; i < grid_.cells; ++i) rest_[i] = state[grid_.cells + i] == 0.0;
}

double RampFlowScheme::velocity(double h, double q) const {
  return h > physics_.dry_thickness ? q / h : 0.0;
}

RampFlowScheme::Star RampFlowScheme::reconstruct(std::size_t face, double hl, double hr,
                                                 bool with_friction) const {
  double dz = dz_;
  if (with_friction && (hl > physics_.dry_thickness || hr > physics_.dry_thickness)) {
    const double mu = basal_friction_at_rest(physics_.friction, 0.5 * (hl + hr));
    const double cap = mu * grid_.dx() / physics_.earth_pressure;
    dz += std::clamp(-((hr - hl) + dz_), -cap, cap);
  }
  Star s{std::max(0.0, hl - std::max(0.0, dz)), std::max(0.0, hr - std::max(0.0, -dz))};
  if (physics_.gate_face && *physics_.gate_face == face) {
    s.left = std::min(s.left, physics_.gate_opening);
    s.right = std::min(s.right, physics_.gate_opening);
  }
  return s;
}

bool RampFlowScheme::rhs(const double* y, double* dy) {
  const std::size_t n = grid_.cells;
  const double* h = y;
  const double* q = y + n;
  double* dh = dy;
  double* dq = dy + n;
  std::fill(dy, dy + state_size(), 0.0);

  auto interior = [&](std::size_t l, std::size_t r, std::size_t face) {
    const double ul = velocity(h[l], q[l]), ur = velocity(h[r], q[r]);
    // mass: friction at rest included between cells at rest
    const Star m = reconstruct(face, h[l], h[r], rest_[l] && rest_[r]);
    const Star s = reconstruct(face, h[l], h[r], false);  // momentum: gravity only
    const double a = std::max(std::abs(ul) + std::sqrt(gk_ * std::max(s.left, m.left)),
                              std::abs(ur) + std::sqrt(gk_ * std::max(s.right, m.right)));
    const double fh = 0.5 * (m.left * ul + m.right * ur) - 0.5 * a * (m.right - m.left);
    const double fq = 0.5 * (s.left * ul * ul + pressure(s.left) + s.right * ur * ur +
                             pressure(s.right)) -
                      0.5 * a * (s.right * ur - s.left * ul);
    dh[l] -= fh;
    dh[r] += fh;
    dq[l] -= fq + pressure(h[l]) - pressure(s.left);
    dq[r] += fq + pressure(h[r]) - pressure(s.right);
  };
  // A closed end: the ghost cell mirrors the velocity and continues the bed; the mass flux is
  // exactly zero and the momentum flux is that of the mirrored Rusanov problem.
  auto wall_flux = [&](double s, double u_outward) {
    const double a = std::abs(u_outward) + std::sqrt(gk_ * s);
    return s * u_outward * u_outward + pressure(s) + a * s * u_outward;
  };

  for (std::size_t f = 1; f < n; ++f) interior(f - 1, f, f);
  if (physics_.upstream == RampBoundary::Periodic) {
    interior(n - 1, 0, n);
  } else {
    // upstream end (face 0, cell 0 on its right): a closed end
    const double u0 = velocity(h[0], q[0]);
    const double s = reconstruct(0, h[0], h[0], false).right;
    dq[0] += wall_flux(s, -u0) + pressure(h[0]) - pressure(s);
    // downstream end (face n, cell n - 1 on its left)
    const std::size_t l = n - 1;
    const double ul = velocity(h[l], q[l]);
    bool closed = physics_.downstream == RampBoundary::Wall;
    if (!closed) {
      // Free end: a ghost cell continues the ramp with the last cell's thickness and no
      // backward velocity, so a layer leaves as if the ramp went on; nothing ever enters.
      const double ug = std::max(0.0, ul);
      const Star m = reconstruct(n, h[l], h[l], rest_[l]);
      const Star s = reconstruct(n, h[l], h[l], false);
      const double a = std::max(std::abs(ul) + std::sqrt(gk_ * s.left),
                                ug + std::sqrt(gk_ * std::max(s.right, m.right)));
      const double fh = 0.5 * (m.left * ul + m.right * ug) - 0.5 * a * (m.right - m.left);
      const double fq = 0.5 * (s.left * ul * ul + pressure(s.left) + s.right * ug * ug +
                               pressure(s.right)) -
                        0.5 * a * (s.right * ug - s.left * ul);
      if (fh >= 0.0) {
        dh[l] -= fh;
        dq[l] -= fq + pressure(h[l]) - pressure(s.left);
        dy[2 * n] += fh;
      } else {
        closed = true;
      }
    }
    if (closed) {
      const double s = reconstruct(n, h[l], h[l], false).left;
      dq[l] -= wall_flux(s, ul) + pressure(h[l]) - pressure(s);
    }
  }
  const double inv_dx = 1.0 / grid_.dx();
  for (std::size_t i = 0; i < 2 * n; ++i) {
    dy[i] *= inv_dx;
    if (!std::isfinite(dy[i])) {
      failed_cell_ = i % n;
      return false;
    }
  }
  // Gravity along the slope for an upstream wall cell comes from the wall face; for an
  // outflow or periodic end it comes from the interior faces as for every other cell.
  return std::isfinite(dy[2 * n]);
}

void RampFlowScheme::apply_friction(double* y, double dt) const {
  const std::size_t n = grid_.cells;
  const double g_cos = kGravity * std::cos(physics_.angle);
  for (std::size_t i = 0; i < n; ++i) {
    const double h = y[i];
    double& q = y[n + i];
    if (h <= physics_.dry_thickness) {
      q = 0.0;
      continue;
    }
    const double u = q / h;
    const double mu = basal_friction(physics_.friction, h, std::abs(u) / std::sqrt(kGravity * h));
    const double impulse = dt * mu * g_cos * h;
    q = std::abs(q) <= impulse ? 0.0 : q - std::copysign(impulse, q);
  }
}

double RampFlowScheme::max_wave_speed(const double* y) const {
  const std::size_t n = grid_.cells;
  double a = 0.0;
  for (std::size_t i = 0; i < n; ++i)
    a = std::max(a, std::abs(velocity(y[i], y[n + i])) + std::sqrt(gk_ * std::max(0.0, y[i])));
  return a;
}

}  // namespace feedflow
