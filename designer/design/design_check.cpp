#include "designer/design/design_check.hpp"

#include "designer/design/case_inputs.hpp"
#include "designer/design/chute_check.hpp"
#include "designer/design/drum_check.hpp"
#include "designer/design/hopper_check.hpp"

namespace feedflow {

DesignRecord design_check(const Case& c, const ModelChoices& models) {
  DesignRecord record;
  describe_case(c, record);
  std::visit(
      [&](const auto& equipment) {
        using T = std::decay_t<decltype(equipment)>;
        if constexpr (std::is_same_v<T, Hopper>) check_hopper(c, equipment, models, record);
        if constexpr (std::is_same_v<T, Chute>) check_chute(c, equipment, models, record);
        if constexpr (std::is_same_v<T, Drum>) check_drum(c, equipment, record);
      },
      c.equipment);
  return record;
}

}  // namespace feedflow
