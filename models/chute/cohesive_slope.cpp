#include "models/chute/cohesive_slope.hpp"

#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>

namespace feedflow {
namespace {

std::string mm(double m) { return std::to_string(m * 1e3) + " mm"; }

}  // namespace

CohesiveStop cohesive_stopping_depth(const CohesiveSlope& s, double angle) {
  if (!(s.cohesion >= 0.0) || !(s.bulk_density > 0.0) ||
      !(s.friction_angle >= 0.0 && s.friction_angle < std::numbers::pi / 2))
    throw std::invalid_argument("cohesive slope needs c >= 0, rho_b > 0, 0 <= phi < 90 deg");
  if (!(angle > 0.0 && angle < std::numbers::pi / 2))
    throw std::invalid_argument("chute angle must lie in (0, 90) degrees");
  const double inf = std::numeric_limits<double>::infinity();
  if (angle <= s.friction_angle)
    return {{DepositOutcome::NeverFlowsBelowTheta1, inf,
             "never flows: the slope is at or below the friction angle"},
            inf};
  if (s.cohesion == 0.0)
    return {{DepositOutcome::NoDepositAboveTheta2, 0.0,
             "no deposit: a cohesionless layer above its friction angle slides off"},
            0.0};
  const double c = std::cos(angle);
  const double z = s.cohesion / (s.bulk_density * kGravity * c * c *
                                 (std::tan(angle) - std::tan(s.friction_angle)));
  return {{DepositOutcome::Deposit, z * c, "deposit of " + mm(z * c) + " (normal to the plane)"},
          z};
}

StoppingThickness hybrid_stopping_thickness(const PouliquenLaw& law, double cohesion,
                                            double bulk_density, double angle) {
  check(law);
  if (!(cohesion >= 0.0) || !(bulk_density > 0.0))
    throw std::invalid_argument("hybrid h_stop needs c >= 0 and rho_b > 0");
  if (!(angle > 0.0 && angle < std::numbers::pi / 2))
    throw std::invalid_argument("chute angle must lie in (0, 90) degrees");
  const double t = std::tan(angle), t1 = std::tan(law.theta1);
  if (angle <= law.theta1)
    return {DepositOutcome::NeverFlowsBelowTheta1, std::numeric_limits<double>::infinity(),
            "never flows: at or below theta1 no layer flows steadily: a flowing layer of any "
            "thickness comes to rest"};
  const double numerator = law.length * (std::tan(law.theta2) - t) +
                           cohesion / (bulk_density * kGravity * std::cos(angle));
  if (numerator <= 0.0)
    return {DepositOutcome::NoDepositAboveTheta2, 0.0,
            "no deposit: above theta2 the cohesion is too small to hold a layer"};
  const double h = numerator / (t - t1);
  return {DepositOutcome::Deposit, h, "deposit of " + mm(h)};
}

}  // namespace feedflow
