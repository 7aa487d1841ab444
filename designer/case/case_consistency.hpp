#pragma once
// Cross-checks between a case's equipment and its material, at the validity limits of the
// reduced models: what a model would refuse (or turn into a non-finite number) is refused here,
// as an input error naming the equipment key, its valid range and the material values behind it.
#include <string>
#include <vector>

#include "models/core/field_spec.hpp"
#include "models/equipment/drum.hpp"
#include "models/equipment/hopper.hpp"
#include "models/material/material.hpp"

namespace feedflow {

// `wall_from_material`: the hopper gives no wall friction angle and takes the material's.
std::vector<FieldProblem> check_against_material(const Hopper& hopper, const Material& material,
                                                 bool wall_from_material);
std::vector<FieldProblem> check_against_material(const Drum& drum, const Material& material);

}  // namespace feedflow
