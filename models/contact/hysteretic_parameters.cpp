#include "models/contact/hysteretic_parameters.hpp"

#include <cmath>

#include "models/contact/restitution_damping.hpp"
#include "models/core/errors.hpp"

namespace feedflow {

HystereticParameters HystereticParameters::from_material(const DemContactParameters& p) {
  if (std::abs(p.chi - 2.0) > 1e-12)
    throw InputError("", "chi",
                     "the hysteretic laws implement the loading power chi = 2 only (as the "
                     "seed's software); got " + std::to_string(p.chi));
  HystereticParameters h;
  h.alpha = p.alpha_prime;
  h.a1 = p.a1;
  h.a2 = p.a2;
  h.a3 = p.a3;
  h.c = p.c;
  h.cohesion_stiffness = p.k_nc * p.a2;
  h.damping_factor = linear_damping_factor(p.restitution);
  return h;
}

}  // namespace feedflow
