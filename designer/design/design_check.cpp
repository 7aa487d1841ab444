#include "designer/design/design_check.hpp"

#include "designer/design/case_inputs.hpp"
#include "designer/design/chute_check.hpp"
#include "designer/design/drum_check.hpp"
#include "designer/design/hopper_check.hpp"
#include "designer/design/verdict_builder.hpp"

namespace feedflow {

DesignRecord design_check(const Case& c, const ModelChoices& models) {
  DesignRecord record;
  describe_case(c, record);
  VerdictBuilder verdict;
  std::visit(
      [&](const auto& equipment) {
        using T = std::decay_t<decltype(equipment)>;
        if constexpr (std::is_same_v<T, Hopper>) check_hopper(c, equipment, models, record, verdict);
        if constexpr (std::is_same_v<T, Chute>) check_chute(c, equipment, models, record, verdict);
        if constexpr (std::is_same_v<T, Drum>) check_drum(c, equipment, record, verdict);
      },
      c.equipment);
  record.verdict = verdict.verdict();
  if (!verdict.judged()) record.verdict.status = VerdictStatus::unknown;
  return record;
}

}  // namespace feedflow
