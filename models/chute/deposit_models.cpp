#include "models/chute/deposit_models.hpp"

#include "models/chute/chute_release.hpp"
#include "models/core/errors.hpp"
#include "models/units/quantity_format.hpp"

namespace feedflow {
namespace {

std::optional<ChuteDeposit> release(const Chute& chute, const PouliquenLaw& law) {
  // 10 mm cells: the second-order scheme leaves the seed ramp's mid-ramp deposit within 0.2 % of
  // its refined value and a drained layer within 3 % of h_stop even when h_stop is a third of
  // a cell (37 deg); a 2 m ramp runs to rest in about 0.1-0.2 s.
  ChuteReleaseOptions options;
  options.cell_size = 10e-3;
  RampFlowResult run = run_chute_release(chute, law, options);
  if (!run.stopped)
    throw NumericalFailure("the L1 chute release did not come to rest within " +
                           format_quantity(options.settings.end_time, "s") + "; the front was still moving");
  return ChuteDeposit{std::move(run), options.cell_size};
}

std::optional<ChuteDeposit> none(const Chute&, const PouliquenLaw&) { return std::nullopt; }

constexpr ChuteDepositModel kDepositRows[] = {
    {{"l1", Rung::L1,
      "depth-averaged release from the bin, run to rest (Savage-Hutter, Pouliquen friction)"},
     &release},
    {{"none", Rung::L0, "no release: the stopping thickness (L0) stands alone"}, &none},
};

constexpr ModelTable<ChuteDepositModel> kDepositTable{"chute.deposit", "deposit after a release",
                                                      kDepositRows};

}  // namespace

const ModelTable<ChuteDepositModel>& chute_deposit_models() { return kDepositTable; }

}  // namespace feedflow
