#include "models/chute/stopping_thickness_models.hpp"

#include "models/chute/cohesive_slope.hpp"

namespace feedflow {
namespace {

StoppingThickness pouliquen(const PouliquenLaw& law, const Material&, double angle) {
  return stopping_thickness(law, angle);
}

StoppingThickness hybrid(const PouliquenLaw& law, const Material& m, double angle) {
  return hybrid_stopping_thickness(law, m.surface_flow->cohesion, m.bulk.density, angle);
}

constexpr StoppingThicknessModel kStoppingThicknessRows[] = {
    {{"pouliquen", Rung::L0, "Pouliquen h_stop law (Forterre & Pouliquen 2003)"}, &pouliquen},
    {{"hybrid", Rung::L0, "Pouliquen h_stop law with low-stress cohesion (hybrid)"}, &hybrid},
};

constexpr ModelTable<StoppingThicknessModel> kStoppingThicknessTable{
    "chute.stopping_thickness", "stopping thickness", kStoppingThicknessRows};

}  // namespace

const ModelTable<StoppingThicknessModel>& stopping_thickness_models() {
  return kStoppingThicknessTable;
}

}  // namespace feedflow
