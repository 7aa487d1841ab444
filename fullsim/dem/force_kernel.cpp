#include "fullsim/dem/force_kernel.hpp"

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

// One force_kernel_normal_<I>.cpp per normal part.
static_assert(NormalParts::kSize == 4,
              "a normal part was added or removed: add or remove its "
              "fullsim/dem/force_kernel_normal_<I>.cpp");

std::unique_ptr<ForceKernel> make_force_kernel(const ContactLawChoice& choice,
                                               const DemParameters& dem) {
  return choice.normal.visit([&](auto normal) {
    using Normal = typename decltype(normal)::type;
    return make_force_kernel_of_normal<NormalParts::index_of<Normal>()>(choice, dem);
  });
}

}  // namespace feedflow
