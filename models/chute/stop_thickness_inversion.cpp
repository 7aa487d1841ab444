#include "models/chute/stop_thickness_inversion.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace feedflow {

PouliquenLaw invert_stopping_thickness(double theta1, const StopMeasurement& first,
                                       const StopMeasurement& second) {
  if (!(first.thickness > 0.0 && second.thickness > 0.0))
    throw std::invalid_argument("h_stop inversion: measured thicknesses must be > 0");
  if (!(first.angle > theta1 && second.angle > theta1))
    throw std::invalid_argument("h_stop inversion: both angles must exceed theta1");
  if (first.angle == second.angle)
    throw std::invalid_argument("h_stop inversion: the two angles must differ");
  const double T1 = std::tan(theta1), t1 = std::tan(first.angle), t2 = std::tan(second.angle);
  const double r = first.thickness / second.thickness;
  const double denominator = r * (t1 - T1) - (t2 - T1);
  if (denominator == 0.0)
    throw std::invalid_argument("h_stop inversion: the measurements fit theta2 = 90 degrees");
  const double T2 = (r * t2 * (t1 - T1) - t1 * (t2 - T1)) / denominator;
  if (!(T2 > std::max(t1, t2)))
    throw std::invalid_argument(
        "h_stop inversion: the thicknesses must fall as the angle rises (fitted theta2 lies "
        "below a measured angle)");
  PouliquenLaw law;
  law.theta1 = theta1;
  law.theta2 = std::atan(T2);
  law.length = first.thickness * (t1 - T1) / (T2 - t1);
  return law;
}

}  // namespace feedflow
