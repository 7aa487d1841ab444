#include "fullsim/dem/force_kernel.hpp"

#include "fullsim/dem/law_forces.hpp"

namespace feedflow {

int lane_bits_available() {
#if defined(__x86_64__)
  static const int bits = [] {
    const bool avx2 = __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
    const bool avx512 = avx2 && __builtin_cpu_supports("avx512f") &&
                        __builtin_cpu_supports("avx512vl") && __builtin_cpu_supports("avx512dq");
    return avx512 ? 512 : avx2 ? 256 : 128;
  }();
  return bits;
#else
  return 128;
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
