#include "designer/design/judge.hpp"

namespace feedflow {

Verdict judge(const Case& c, const Estimates& estimates) {
  return std::visit(
      [&](const auto& equipment) {
        using T = std::decay_t<decltype(equipment)>;
        if constexpr (std::is_same_v<T, Hopper>) return judge_hopper(equipment, c.design, estimates);
        if constexpr (std::is_same_v<T, Chute>) return judge_chute(equipment, c.design, estimates);
        if constexpr (std::is_same_v<T, Drum>) return judge_drum(equipment, c.design, estimates);
      },
      c.equipment);
}

}  // namespace feedflow
