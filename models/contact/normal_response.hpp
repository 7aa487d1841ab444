#pragma once
// What a normal part hands to the rest of the composed law (models.md 3.3 step 5-7, 4.3).
namespace feedflow {

struct NormalResponse {
  double force = 0.0;                 // elastic/hysteretic force plus damping, before clipping [N]
  double elastic_force = 0.0;         // the same without damping [N]
  double tangential_stiffness = 0.0;  // k_t handed to the `history` tangential part [N/m]
  double tangential_damping = 0.0;    // gamma_t handed on with it [N s/m]
};

}  // namespace feedflow
