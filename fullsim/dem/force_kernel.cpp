#include "fullsim/dem/force_kernel.hpp"

#include "fullsim/dem/law_forces.hpp"

namespace feedflow {

bool wide_lanes_available() {
#if defined(__x86_64__)
  static const bool yes = __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
  return yes;
#else
  return false;
#endif
}

std::unique_ptr<ForceKernel> make_force_kernel(const ContactLawChoice& choice,
                                               const DemParameters& dem) {
  return with_contact_law(choice, [&](auto tag) -> std::unique_ptr<ForceKernel> {
    using Law = typename decltype(tag)::type;
    return std::make_unique<LawForces<Law>>(dem);
  });
}

}  // namespace feedflow
