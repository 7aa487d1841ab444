#pragma once
// The chute design check: evaluate (stopping thickness on the ramp by the chosen law over the
// uncertainty of theta1, theta2 and L, rung L0; the deposit of a release from the bin, rung
// L1), judge (judge_chute: against the case's [design] targets) and explain (assumptions,
// charts).
#include <optional>
#include <vector>

#include "designer/case/case.hpp"
#include "designer/design/design_detail.hpp"
#include "designer/design/model_choices.hpp"
#include "models/chute/deposit_models.hpp"
#include "models/chute/stopping_thickness_models.hpp"
#include "models/core/design_record.hpp"

namespace feedflow {

void check_chute(const Case& c, const Chute& chute, const ModelChoices& models, DesignDetail detail,
                 DesignRecord& record);

// The material as the chute check sees it: its [surface_flow] with theta2 and L from its
// [calibration.chute] when it has one. Throws InputError (naming the file and key) without
// [surface_flow], or for a calibrated theta2 not above theta1.
Material chute_material(const Material& m);

// The chosen law's stopping thickness at `angle` (rad), and its band over the uncertainty of
// theta1, theta2 and L, widened by a chute calibration's largest error. `m`: a chute_material.
// Near theta1 the corners need not agree on whether the material flows at all: `edge` is then
// the outcome of a corner that disagrees with the nominal law (a corner that never flows leaves
// the band without a top; the band's numbers are those of the corners that leave a layer), and
// `edge_theta1` that corner's theta1.
struct StoppingThicknessBand {
  StoppingThickness nominal;
  double low = 0.0, high = 0.0;  // [m]
  std::optional<DepositOutcome> edge;
  double edge_theta1 = 0.0;  // [rad]
};
StoppingThicknessBand stopping_thickness_band(const Material& m, const StoppingThicknessModel& stop,
                                              double angle);

// The corners of the uncertainty of theta1, theta2 and L of a material's surface-flow law.
PouliquenLaw pouliquen_law_of(const SurfaceFlowProperties& s);
std::vector<PouliquenLaw> corner_laws(const SurfaceFlowProperties& s);

// The chute's charts: stopping thickness against angle, and with a release the deposit profile,
// the front and the velocity against time.
std::vector<Chart> chute_charts(const Chute& chute, const Material& m, const StoppingThicknessModel& stop,
                                const std::optional<ChuteDeposit>& deposit);

}  // namespace feedflow
