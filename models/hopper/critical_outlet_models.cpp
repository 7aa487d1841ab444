#include "models/hopper/critical_outlet_models.hpp"

#include <algorithm>

namespace feedflow {
namespace {

using StaticArch = std::optional<CriticalOutlet>;

CriticalWidth jenike(const CriticalOutlet& j, const StaticArch&) { return {j.width, j.model}; }

CriticalWidth envelope(const CriticalOutlet& j, const StaticArch& arch) {
  if (!arch) return jenike(j, arch);
  return {std::max(j.width, arch->width), "envelope of Jenike H(theta) and static-arch H_a"};
}

CriticalWidth static_arch(const CriticalOutlet& j, const StaticArch& arch) {
  return arch ? CriticalWidth{arch->width, arch->model} : jenike(j, arch);
}

constexpr CriticalOutletModel kCriticalOutletRows[] = {
    {{"envelope", Rung::L0,
      "the larger of Jenike's H(theta) and the static-arch H_a (Jenike alone for cones)"},
     &envelope},
    {{"jenike", Rung::L0, "Jenike's critical outlet with H(theta) only"}, &jenike},
    {{"static_arch", Rung::L0,
      "the static-arch H_a, wall-friction limited (plane hoppers; Jenike for cones)"},
     &static_arch},
};

constexpr ModelTable<CriticalOutletModel> kCriticalOutletTable{
    "hopper.critical_outlet", "critical outlet width", kCriticalOutletRows};

}  // namespace

const ModelTable<CriticalOutletModel>& critical_outlet_models() { return kCriticalOutletTable; }

}  // namespace feedflow
