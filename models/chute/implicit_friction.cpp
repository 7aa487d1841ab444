#include "models/chute/implicit_friction.hpp"

#include <algorithm>
#include <cmath>

namespace feedflow {

ImplicitFriction::ImplicitFriction(const PouliquenLaw& law)
    : law_(law), tan1_(std::tan(law.theta1)), span_(std::tan(law.theta2) - tan1_) {}

double ImplicitFriction::at_rest(double h) const {
  return span_ == 0.0 ? tan1_ : tan1_ + span_ / (h / law_.length + 1.0);
}

double ImplicitFriction::coefficient(double h, double froude) const {
  if (span_ == 0.0) return tan1_;
  const double fr = froude + law_.gamma;
  if (fr <= law_.beta) return at_rest(h);
  return tan1_ + span_ * law_.length * fr / (law_.beta * h + law_.length * fr);
}

double ImplicitFriction::speed_after(double h, double u_star, double k) const {
  if (span_ == 0.0) return std::max(0.0, u_star - k * tan1_);  // Coulomb: constant mu
  const double c = std::sqrt(kGravity * h);
  const double L = law_.length, bh = law_.beta * h;
  // mu at zero speed: mu_stop(h), or the dynamic value at Fr = 0 when Gamma >= beta
  const double mu0 = law_.gamma <= law_.beta
                         ? at_rest(h)
                         : tan1_ + span_ * L * law_.gamma / (bh + L * law_.gamma);
  if (u_star <= k * mu0) return 0.0;  // held inside the Coulomb cone
  // static branch, mu = mu_stop(h), while Fr + Gamma <= beta
  const double u_static = u_star - k * mu0;
  if (law_.gamma <= law_.beta && u_static / c + law_.gamma <= law_.beta) return u_static;
  // dynamic branch in w = Fr + Gamma: mu = tan1 + span L w/(beta h + L w), so
  // (c w + b)(beta h + L w) + k span L w = 0 with b = k tan1 - u* - c Gamma < 0;
  // the left side is negative at the branch start and grows: the larger root.
  const double b = k * tan1_ - u_star - c * law_.gamma;
  const double a2 = c * L, a1 = c * bh + b * L + k * span_ * L, a0 = b * bh;
  const double root = std::sqrt(std::max(0.0, a1 * a1 - 4.0 * a2 * a0));
  const double w = a1 <= 0.0 ? (-a1 + root) / (2.0 * a2) : -2.0 * a0 / (a1 + root);
  return std::clamp(c * (w - law_.gamma), 0.0, u_star);
}

}  // namespace feedflow
