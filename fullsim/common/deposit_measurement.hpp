#pragma once
// The deposit left on a ramp measured the same way on every rung, from its thickness profile
// along the slope (the DEM's highest particle top per bin, as the seed's DEM measured; the
// CEL's column thickness, as the seed's FEM did): the thickness at mid-ramp is the mean over
// the points within 5 % of the ramp length of mid-ramp, its band their range.
#include <cstddef>
#include <vector>

namespace feedflow {

struct DepositThickness {
  double value = 0.0;           // [m]
  double low = 0.0, high = 0.0; // [m]
  std::size_t points = 0;       // in the window (0: none, value 0)
};

// `x`: distance along the slope from the gate [m]; `thickness` normal to the ramp [m].
DepositThickness mid_ramp_thickness(const std::vector<double>& x, const std::vector<double>& thickness,
                                    double ramp_length, double half_window = 0.05);

}  // namespace feedflow
