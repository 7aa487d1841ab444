#pragma once
// Fits the flow function's strength in each hopper.critical_outlet row (a factor s on sigma_c)
// to a full rung's critical outlet widths. The rung gives each B_c as a bracket from a bisection
// on the outlet (the widest outlet seen to arch, the narrowest seen to flow); the fit takes the
// geometric middle of each bracket as its reference and minimises the squared log error over
// the fitted points, through the design check's own evaluation (so `design` reproduces the fit).
// It also gives the range of s over which the reduced B_c stays inside every fitted bracket:
// with one point the fit is exact and that range is what the rung's bracket allows.
#include <string>
#include <vector>

#include "designer/calibrate/discharge_fit.hpp"

namespace feedflow {

// One semi-angle: the hopper there (its wall friction as the rung ran it) and the rung's bracket.
struct ArchingObservation {
  Hopper hopper;
  double arches_at = 0.0;  // [m] widest outlet the rung saw arch
  double flows_at = 0.0;   // [m] narrowest outlet the rung saw flow
  bool held_out = false;
  double reference() const;  // [m] the bracket's geometric middle
};

struct ArchingRowFit {
  const CriticalOutletModel* row = nullptr;
  double scale = 1.0;  // fitted factor on sigma_c
  double scale_low = 0.0,
         scale_high = 0.0;  // every fitted bracket holds B_c within; low > high: none
  std::vector<double> width_before,
      width_after;  // [m] the row's B_c per observation, at 1 and at `scale`
  double fit_rms_before = 0.0,
         fit_rms_after = 0.0;  // relative error to the references, fitted points
  double held_out_max_before = 0.0,
         held_out_max_after = 0.0;              // largest relative error, held-out points
  std::size_t held_before = 0, held_after = 0;  // brackets (all points) holding the row's B_c
};

// `material`: the published material (its own arching calibration ignored); `models`: the
// design check's flow-factor row. Every hopper.critical_outlet row is fitted. Throws
// std::invalid_argument without fitted observations, with hoppers of two geometries, or with a
// bracket that is not one (arches_at >= flows_at).
std::vector<ArchingRowFit> fit_arching(const std::vector<ArchingObservation>& observations,
                                       HopperMaterial material, const HopperModels& models = {});

}  // namespace feedflow
