#include "models/hopper/radial_stress_field.hpp"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_odeiv2.h>

#include <cmath>
#include <numbers>
#include <sstream>
#include <stdexcept>
#include <string>

#include "models/core/errors.hpp"
#include "models/numerics/brent_root.hpp"
#include "models/numerics/gsl_errors_as_status.hpp"
#include "models/units/angle.hpp"

namespace feedflow {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kStartAngle = 1e-6;       // start off the axis, where cot(theta) is singular
constexpr double kFallenAway = 0.2;        // psi < pi/2 - 0.2: the path left the arched field
constexpr double kSingularGap = 1e-6;      // distance to S = cos 2psi treated as reaching it
constexpr double kRelTol = 1e-9;
constexpr double kAbsTol = 1e-12;

std::string deg(double rad) {
  std::ostringstream s;
  s << in_degrees(rad) << " deg";
  return s.str();
}

struct FieldParameters {
  int m;
  double S;  // sin delta
};

// d(s, psi)/d(theta) from the equilibrium equations of section 1.2.
int field_rhs(double theta, const double y[], double dydt[], void* params) {
  const auto* p = static_cast<const FieldParameters*>(params);
  const double s = y[0], psi = y[1];
  const double c = std::cos(2.0 * psi), t = std::sin(2.0 * psi);
  const double S = p->S;
  const double m = p->m;
  const double cot = m == 0 ? 0.0 : 1.0 / std::tan(theta);
  const double a1 = -std::cos(theta) - s * (1.0 + (3.0 + m) * S * c - m * S + m * S * t * cot);
  const double a2 = std::sin(theta) - s * S * ((3.0 + m) * t - m * (1.0 + c) * cot);
  const double gap = S - c;
  if (std::abs(gap) < 1e-14 || s <= 0.0) return GSL_EBADFUNC;
  dydt[0] = (a1 * t - a2 * c) / gap;
  dydt[1] = (S * t * a2 - (1.0 - S * c) * a1) / (2.0 * s * S * gap);
  return GSL_SUCCESS;
}

struct OdeWorkspace {
  gsl_odeiv2_step* step;
  gsl_odeiv2_control* control;
  gsl_odeiv2_evolve* evolve;
  OdeWorkspace()
      : step(gsl_odeiv2_step_alloc(gsl_odeiv2_step_rk8pd, 2)),
        control(gsl_odeiv2_control_y_new(kAbsTol, kRelTol)),
        evolve(gsl_odeiv2_evolve_alloc(2)) {}
  ~OdeWorkspace() {
    gsl_odeiv2_evolve_free(evolve);
    gsl_odeiv2_control_free(control);
    gsl_odeiv2_step_free(step);
  }
  OdeWorkspace(const OdeWorkspace&) = delete;
  OdeWorkspace& operator=(const OdeWorkspace&) = delete;
};

struct WallState {
  double mismatch;     // F = psi(theta_w) - psi_w (or psi at a guard stop - psi_w)
  double wall_stress;  // s(theta_w); NaN-free only when `reached_wall`
  bool reached_wall;
};

WallState integrate_to_wall(FlowGeometry g, double theta_w, double delta, double phi_w,
                            double s0) {
  if (!(theta_w > kStartAngle && theta_w < 0.5 * kPi))
    throw std::invalid_argument("hopper semi-angle must lie in (0, 90) deg");
  const double beta = wall_stress_angle(delta, phi_w);
  const double psi_w = 0.5 * kPi + beta;
  FieldParameters params{geometry_index(g), std::sin(delta)};
  const double S = params.S;
  const double m = params.m;
  // psi at which S - cos 2psi = 0 on the arched branch: 3pi/4 + delta/2.
  const double psi_singular = kPi - 0.5 * std::acos(S);

  const double dpsi0 = (1.0 + 1.0 / s0 - (3.0 + 2.0 * m) * S) / (2.0 * (1.0 + m) * S);
  double y[2] = {s0, 0.5 * kPi + dpsi0 * kStartAngle};
  double theta = kStartAngle;
  double h = 1e-4;
  OdeWorkspace ws;
  gsl_odeiv2_system sys{field_rhs, nullptr, 2, &params};
  const GslErrorsAsStatus quiet;
  for (int steps = 0; theta < theta_w; ++steps) {
    if (steps > 100000)
      throw NumericalFailure("radial stress field: more than 100000 steps from the axis to " +
                             deg(theta_w) + " (s0 = " + std::to_string(s0) + ")");
    const int status = gsl_odeiv2_evolve_apply(ws.evolve, ws.control, ws.step, &sys, &theta,
                                               theta_w, &h, y);
    if (y[1] >= psi_singular - kSingularGap || (status != GSL_SUCCESS && y[1] > psi_w))
      return {psi_singular - psi_w, 0.0, false};  // reached S = cos 2psi: F > 0
    if (y[1] < 0.5 * kPi - kFallenAway || y[0] <= 0.0 || status != GSL_SUCCESS)
      return {0.5 * kPi - kFallenAway - psi_w, 0.0, false};  // fell away: F < 0
  }
  return {y[1] - psi_w, y[0], true};
}

struct ShootingData {
  FlowGeometry g;
  double theta_w, delta, phi_w;
};

double mismatch_of_log_s0(double log_s0, const ShootingData* d) {
  return integrate_to_wall(d->g, d->theta_w, d->delta, d->phi_w, std::exp(log_s0)).mismatch;
}

double mismatch_at_min_s0(double theta, const ShootingData* d) {
  return integrate_to_wall(d->g, theta, d->delta, d->phi_w, kMinAxisStress).mismatch;
}

}  // namespace

double max_axis_stress(FlowGeometry g, double delta) {
  const double k = (3.0 + 2.0 * geometry_index(g)) * std::sin(delta) - 1.0;
  return k > 1.0 / 1e3 ? 1.0 / k : 1e3;
}

double radial_field_wall_mismatch(FlowGeometry g, double theta_w, double delta, double phi_w,
                                  double s0) {
  if (!(s0 > 0.0)) throw std::invalid_argument("axis stress s0 must be positive");
  return integrate_to_wall(g, theta_w, delta, phi_w, s0).mismatch;
}

std::optional<RadialStressField> solve_radial_stress_field(FlowGeometry g, double theta_w,
                                                           double delta, double phi_w) {
  ShootingData data{g, theta_w, delta, phi_w};
  const double lo = std::log(kMinAxisStress);
  const double hi = std::log(max_axis_stress(g, delta));
  const std::string where = std::string("radial stress field (") + to_string(g) + ", theta " +
                            deg(theta_w) + ", delta " + deg(delta) + ", phi_w " + deg(phi_w) +
                            ")";
  if (mismatch_of_log_s0(lo, &data) <= 0.0) return std::nullopt;  // beyond the existence limit
  if (mismatch_of_log_s0(hi, &data) >= 0.0)
    throw NumericalFailure(where + ": psi stays above the wall value for every s0 up to " +
                           std::to_string(std::exp(hi)) + "; no sign change to shoot on");
  const double log_s0 = brent_root([&](double x) { return mismatch_of_log_s0(x, &data); }, lo,
                                   hi, 1e-12, 0.0, where);
  const WallState wall = integrate_to_wall(g, theta_w, delta, phi_w, std::exp(log_s0));
  if (!wall.reached_wall || std::abs(wall.mismatch) > 1e-6) {
    // F changes sign across a guard (a path stopped at the singular line or fallen away on
    // one side) instead of through psi(theta_w) = psi_w: no admissible field in the bracket.
    // Met for delta = 25 deg cones beyond the conical limit.
    const double step = 1e-9;
    const WallState below = integrate_to_wall(g, theta_w, delta, phi_w, std::exp(log_s0 - step));
    const WallState above = integrate_to_wall(g, theta_w, delta, phi_w, std::exp(log_s0 + step));
    if (!below.reached_wall || !above.reached_wall) return std::nullopt;
  }
  if (!wall.reached_wall || std::abs(wall.mismatch) > 1e-6)
    throw NumericalFailure(where + ": the shooting converged on a jump of F(s0), not a root "
                                   "(mismatch " + std::to_string(wall.mismatch) + " rad)");
  const double ff = (1.0 + std::sin(delta)) * wall.wall_stress * jenike_arch_factor(g, theta_w) /
                    (2.0 * std::sin(theta_w));
  return RadialStressField{std::exp(log_s0), wall.wall_stress, ff};
}

std::optional<double> radial_field_limit_angle(FlowGeometry g, double delta, double phi_w) {
  ShootingData data{g, 0.0, delta, phi_w};
  const double lo = 1.0 * kPi / 180.0, hi = 89.0 * kPi / 180.0;
  if (mismatch_at_min_s0(hi, &data) > 0.0) return std::nullopt;
  if (mismatch_at_min_s0(lo, &data) <= 0.0)
    throw NumericalFailure("radial stress field: no admissible field even at 1 deg (delta " +
                           deg(delta) + ", phi_w " + deg(phi_w) + ")");
  return brent_root([&](double t) { return mismatch_at_min_s0(t, &data); }, lo, hi, 1e-7, 0.0,
                    "radial stress field existence limit");
}

}  // namespace feedflow
