#pragma once
// Seed Table 1's pine as the CEL scene tests fill it: the hypoplastic model, and the bulk density
// and void ratio of the fill.
#include "fullsim/cel/cel_scene.hpp"
#include "models/hypoplastic/hypoplastic_model.hpp"

namespace feedflow::testing {

inline const cel::SceneMaterial kPine{290.0, 0.7102};
inline HypoplasticModel pine() { return make_hypoplastic_model(loblolly_pine_table1()); }

}  // namespace feedflow::testing
