#include "designer/simulate/drum_angle_interval.hpp"

#include "models/units/angle.hpp"

namespace feedflow {

void add_angle_interval(Estimates& results, std::optional<double> half_width, Rung rung) {
  if (!half_width) return;
  results.emplace_back(interval_key("dynamic_angle_of_repose"),
                       Estimate{*half_width / kDegree, "deg", std::nullopt, std::nullopt,
                                "half-width of the 95 % interval of the angle's mean (Student t "
                                "over the kept batch means)",
                                rung, ""});
}

}  // namespace feedflow
