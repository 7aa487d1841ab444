#pragma once
// Parameters and per-contact history of the Chen et al. (2022) hysteretic normal law (seed
// Eq. 7, models.md 3.1-3.2), shared by its two unloading variants.
#include <cstddef>

#include "models/material/dem_parameters.hpp"

namespace feedflow {

struct HystereticParameters {
  double alpha = 0.0;           // alpha', loading force scaling [-]
  double a1 = 0.0;              // growth of the loading stiffness with the largest overlap [N/m^3]
  double a2 = 0.0;              // virgin loading stiffness k1 [N/m^2]
  double a3 = 0.0;              // unloading / loading stiffness ratio [-]
  double c = 0.0;               // unloading force scaling [m^2]
  double cohesion_stiffness = 0.0;  // k_c = K_nc A2, used when cohesion is on
  // Model 2's -k_c delta floor below delta0 (models.md 3.5 [I]): only with the k_nc cohesion
  // part (ContactLaw sets it through `cohesive()`); the peer's model 2 has none.
  bool cohesion_floor = false;
  double damping_factor = 0.0;  // 1/(1 + (pi/ln e)^2) from the restitution
  // Table 2 mapping (models.md 3.1). Throws InputError when chi != 2 (the seed software
  // hard-codes the square).
  static HystereticParameters from_material(const DemContactParameters& p);
};

// History slots, all zeroed when the contact opens; names from models.md 3.2.
namespace hysteretic_slot {
inline constexpr std::size_t max_overlap = 0;          // delta_max
inline constexpr std::size_t plastic_overlap = 1;      // delta0
inline constexpr std::size_t loading_stiffness = 2;    // k1
inline constexpr std::size_t plastic_overlap_old = 3;  // delta0 of the loading branch just used
inline constexpr std::size_t loading_stiffness_old = 4;  // k1_old
inline constexpr std::size_t previous_overlap = 5;     // delta at the previous step
inline constexpr std::size_t cohesion_overlap = 6;     // delta_min (model 1 only)
inline constexpr std::size_t unloading_shape = 7;      // beta_n
inline constexpr std::size_t loading_offset = 8;       // f0 (seed f1)
inline constexpr std::size_t loading_offset_old = 9;   // f0_old
inline constexpr std::size_t count = 10;
}  // namespace hysteretic_slot

}  // namespace feedflow
