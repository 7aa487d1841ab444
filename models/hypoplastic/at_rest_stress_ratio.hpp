#pragma once
// K0 of the hypoplastic model: the lateral/vertical stress ratio that oedometric compression
// (D = diag(0, 0, -1)) leaves unchanged, T° parallel to T, at mean pressure p and void ratio e.
// Hypoplastic stress paths in the oedometer are attracted to it; it drifts with e (models.md 1.7
// item 2: 0.367 -> 0.397 for pine at low stress).
#include "models/hypoplastic/hypoplastic_model.hpp"

namespace feedflow {

// Throws std::invalid_argument for p <= 0 or e <= 0, NumericalFailure when no ratio in
// [0.02, 1] makes the rate proportional.
double at_rest_stress_ratio(const HypoplasticModel& model, double mean_pressure, double void_ratio);

}  // namespace feedflow
