#pragma once
// Cohesion parts. The attractive branch of seed Eq. 7 (F_nc = -K_nc A2 delta, models.md 3.4)
// lives in the hysteretic normal laws; the cohesion part decides whether it may act:
// - `none`: the normal force is clipped at zero (LIGGGHTS `limitForce`, on in all INL decks),
//   so no contact pulls, not even through its damping;
// - `k_nc`: no clipping; the K_nc branch of the hysteretic law acts. Only the hysteretic laws
//   have one (the registry refuses k_nc with hertz or hooke).
#include <cstddef>
#include <string_view>

#include "models/material/dem_parameters.hpp"

namespace feedflow {

struct NoCohesion {
  static constexpr std::string_view kKeyword = "none";
  static constexpr std::string_view kSummary = "normal force clipped at zero (limitForce)";
  static constexpr std::size_t kHistorySize = 0;
  static constexpr bool kNeedsCohesionBranch = false;
  static NoCohesion from_material(const DemContactParameters&) { return {}; }
  static double normal_force(double f) { return f > 0.0 ? f : 0.0; }
};

struct KncCohesion {
  static constexpr std::string_view kKeyword = "k_nc";
  static constexpr std::string_view kSummary =
      "the hysteretic law's F = -K_nc A2 delta branch acts (no clipping)";
  static constexpr std::size_t kHistorySize = 0;
  static constexpr bool kNeedsCohesionBranch = true;
  static KncCohesion from_material(const DemContactParameters&) { return {}; }
  static double normal_force(double f) { return f; }
};

}  // namespace feedflow
