#pragma once
// Seed Table 1 (milled loblolly pine, Gudehus-Bauer hypoplastic) as the model the hypoplastic
// tests integrate.
#include "models/hypoplastic/hypoplastic_model.hpp"

namespace feedflow::testing {

inline const HypoplasticModel kPine = make_hypoplastic_model(loblolly_pine_table1());

}  // namespace feedflow::testing
