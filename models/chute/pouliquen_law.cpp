#include "models/chute/pouliquen_law.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>
#include <stdexcept>

#include "models/core/errors.hpp"
#include "models/numerics/brent_root.hpp"
#include "models/units/angle.hpp"

namespace feedflow {
namespace {

constexpr double kHalfPi = std::numbers::pi / 2;

void check_angle(double angle) {
  if (!(angle > 0.0 && angle < kHalfPi))
    throw std::invalid_argument("chute angle must lie in (0, 90) degrees");
}

std::string degrees(double radians) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.1f deg", in_degrees(radians));
  return buf;
}

StoppingThickness outside_band(double angle, double theta1, double theta2) {
  if (angle >= theta2)
    return {DepositOutcome::NoDepositAboveTheta2, 0.0,
            "no deposit: at " + degrees(angle) + " (at or above theta2 = " + degrees(theta2) +
                ") every layer keeps flowing and the ramp drains"};
  return {DepositOutcome::NeverFlowsBelowTheta1, std::numeric_limits<double>::infinity(),
          "never flows: at " + degrees(angle) + " (at or below theta1 = " + degrees(theta1) +
              ") no layer flows steadily: a flowing layer of any thickness comes to rest"};
}

}  // namespace

void check(const PouliquenLaw& law) {
  if (!(law.theta1 >= 0.0 && law.theta1 < law.theta2 && law.theta2 < kHalfPi))
    throw std::invalid_argument("Pouliquen law needs 0 <= theta1 < theta2 < 90 degrees");
  if (!(law.length > 0.0)) throw std::invalid_argument("Pouliquen law needs L > 0");
  if (!(law.beta > 0.0) || !(law.gamma >= 0.0))
    throw std::invalid_argument("Pouliquen flow rule needs beta > 0 and Gamma >= 0");
}

const char* to_string(DepositOutcome o) {
  switch (o) {
    case DepositOutcome::Deposit: return "a layer stays behind";
    case DepositOutcome::NoDepositAboveTheta2: return "no deposit (above theta2)";
    case DepositOutcome::NeverFlowsBelowTheta1: return "never flows (below theta1)";
  }
  return "a layer stays behind";
}

std::optional<DepositOutcome> deposit_outcome_from_string(std::string_view text) {
  for (auto o : {DepositOutcome::Deposit, DepositOutcome::NoDepositAboveTheta2, DepositOutcome::NeverFlowsBelowTheta1})
    if (text == to_string(o)) return o;
  return std::nullopt;
}

StoppingThickness stopping_thickness(const PouliquenLaw& law, double angle) {
  check(law);
  check_angle(angle);
  if (angle <= law.theta1 || angle >= law.theta2)
    return outside_band(angle, law.theta1, law.theta2);
  const double t = std::tan(angle);
  const double h = law.length * (std::tan(law.theta2) - t) / (t - std::tan(law.theta1));
  return {DepositOutcome::Deposit, h, "deposit of " + std::to_string(h * 1e3) + " mm"};
}

StoppingThickness stopping_thickness(const PouliquenExponentialLaw& law, double angle) {
  if (!(law.theta1 >= 0.0 && law.theta1 < law.theta2 && law.theta2 < kHalfPi) ||
      !(law.decay_length > 0.0))
    throw std::invalid_argument("Pouliquen 1999 law needs 0 <= theta1 < theta2 < 90 deg, A d > 0");
  check_angle(angle);
  if (angle <= law.theta1 || angle >= law.theta2)
    return outside_band(angle, law.theta1, law.theta2);
  const double t1 = std::tan(law.theta1);
  const double h =
      law.decay_length * std::log((std::tan(law.theta2) - t1) / (std::tan(angle) - t1));
  return {DepositOutcome::Deposit, h, "deposit of " + std::to_string(h * 1e3) + " mm"};
}

double flow_rule_froude(const PouliquenLaw& law, double thickness, double angle) {
  const auto stop = stopping_thickness(law, angle);
  if (stop.outcome != DepositOutcome::Deposit)
    throw std::invalid_argument("flow rule: " + stop.words + "; no steady uniform flow");
  if (!(thickness >= 0.0)) throw std::invalid_argument("flow rule: thickness must be >= 0");
  return std::max(0.0, law.beta * thickness / stop.thickness - law.gamma);
}

double flow_rule_velocity(const PouliquenLaw& law, double thickness, double angle) {
  return flow_rule_froude(law, thickness, angle) * std::sqrt(kGravity * thickness);
}

double thickness_for_flow_rate(const PouliquenLaw& law, double q, double angle) {
  const auto stop = stopping_thickness(law, angle);
  if (stop.outcome != DepositOutcome::Deposit)
    throw std::invalid_argument("chute sizing: " + stop.words + "; no steady uniform flow");
  if (!(q > 0.0)) throw std::invalid_argument("chute sizing: flow rate must be > 0");
  const double closed = std::pow(q * stop.thickness / (law.beta * std::sqrt(kGravity)), 0.4);
  if (law.gamma == 0.0) return closed;
  // q(h) = sqrt(g) h^(3/2) (beta h/h_stop - Gamma) rises monotonically from h0 = Gamma h_stop/beta.
  const auto excess_flow = [&](double h) { return h * flow_rule_velocity(law, h, angle) - q; };
  double lo = law.gamma * stop.thickness / law.beta, hi = std::max(2.0 * lo, closed);
  while (excess_flow(hi) < 0.0) hi *= 2.0;
  const BrentSearch root = brent_search(excess_flow, lo, hi, {0.0, 1e-12, 200});
  if (!root.converged())
    throw NumericalFailure("chute sizing: Brent root of q = h u(h) did not converge in [" +
                           std::to_string(lo) + ", " + std::to_string(hi) +
                           "] m; check beta and Gamma");
  return root.root;
}

double basal_friction_at_rest(const PouliquenLaw& law, double h) {
  const double t1 = std::tan(law.theta1), dt = std::tan(law.theta2) - t1;
  if (dt == 0.0) return t1;
  return t1 + dt / (h / law.length + 1.0);
}

double basal_friction(const PouliquenLaw& law, double h, double froude) {
  const double t1 = std::tan(law.theta1), dt = std::tan(law.theta2) - t1;
  if (dt == 0.0) return t1;
  const double fr = froude + law.gamma;
  if (fr <= law.beta) return basal_friction_at_rest(law, h);
  return t1 + dt / (law.beta * h / (law.length * fr) + 1.0);
}

}  // namespace feedflow
