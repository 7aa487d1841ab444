#pragma once
// The rotating-drum design check: evaluate (Froude number, regime and its distance to the
// nearest boundary, critical speeds, the dynamic angle of repose in the rolling regime with the
// no-slip wall friction it needs), judge (judge_drum: against the case's required regime) and
// explain (assumptions, the regime map and the angle against speed).
#include <vector>

#include "designer/case/case.hpp"
#include "designer/design/design_detail.hpp"
#include "models/core/chart.hpp"
#include "models/drum/drum_regime.hpp"

namespace feedflow {

void check_drum(const Case& c, const Drum& drum, DesignDetail detail, DesignRecord& record);

// The regime thresholds of a material's [drum_flow].
DrumRegimeThresholds regime_thresholds(const DrumFlowProperties& d);

// The flowing layer's coefficients the design check uses: the material's [calibration.drum]
// when it has one (`calibration` points at it; `error` is its largest relative error, fit rms
// or held out), else [drum_flow]'s c_delta and no shift.
struct DrumLayer {
  double layer_fraction;  // c_delta [-]
  double friction_shift;  // added to theta1 and theta2 [rad]
  double error;           // [-]
  const DrumCalibration* calibration;
};
DrumLayer drum_layer(const Material& m);

// The dynamic angle of repose of the rolling regime (mu(I) flowing layer with end-wall
// friction), nominal and over +- the uncertainty of theta1 and theta2 and the layer thickness
// range (published) or the calibration's error (calibrated) [rad]. The material has
// [surface_flow] and [drum_flow].
struct AngleOfRepose {
  double nominal, low, high;
};
AngleOfRepose rolling_angle_band(const Drum& drum, const Material& m);

// The drum's charts: the angle of repose against speed (rolling regime, when the material has a
// surface-flow law) and the regime map.
std::vector<Chart> drum_charts(const Drum& drum, const Material& m, const DrumRegimeAssessment& regime);

}  // namespace feedflow
