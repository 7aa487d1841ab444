#include "designer/case/case_consistency.hpp"

#include "models/hopper/discharge_rate.hpp"
#include "models/units/quantity_format.hpp"

namespace feedflow {
namespace {

// Drums under this many median grains across are particle-scale: no continuum flowing layer.
constexpr double kMinDrumGrains = 10.0;

std::string deg(double rad) { return format_quantity(rad, "deg", 4); }
std::string mm(double m) { return format_quantity(m, "mm", 4); }

}  // namespace

std::vector<FieldProblem> check_against_material(const Hopper& h, const Material& m, bool wall_from_material) {
  std::vector<FieldProblem> problems;
  const std::string wall_source =
      wall_from_material ? " (the material's bulk.wall_friction_angle: [hopper] gives none)" : "";
  if (m.flow && h.wall_friction_angle) {
    const double phi_w = *h.wall_friction_angle;
    const double delta = m.flow->effective_friction_angle;
    const double spread = m.flow->wall_friction_uncertainty;
    // The models take the wall over the band phi_w +- spread; a frictionless wall leaves the
    // Janssen stress unbounded, and a wall rougher than the solid shears inside the solid.
    if (!(phi_w > spread) || !(phi_w < delta))
      problems.push_back({"wall_friction_angle",
                          "must lie above the wall-friction uncertainty (" + deg(spread) +
                              ", flow_properties.wall_friction_uncertainty) and below the effective "
                              "angle of internal friction (" + deg(delta) + ") of material " + m.name +
                              ", got " + deg(phi_w) + wall_source});
  }
  if (m.psd) {
    const double narrowest = kBeverlooK * m.psd->d50;
    if (!(h.outlet_width > narrowest))
      problems.push_back({"outlet_width", "must exceed " + format_quantity(kBeverlooK, "", 3) +
                                              " median grain sizes (" + mm(narrowest) + ", psd.d50 of material " +
                                              m.name + "), got " + mm(h.outlet_width) +
                                              ": no narrower outlet passes grains (Beverloo's empty annulus)"});
  }
  return problems;
}

std::vector<FieldProblem> check_against_material(const Drum& d, const Material& m) {
  std::vector<FieldProblem> problems;
  if (m.psd && !(d.diameter >= kMinDrumGrains * m.psd->d50))
    problems.push_back({"diameter", "must be at least " + format_quantity(kMinDrumGrains, "", 3) +
                                        " median grain sizes (" + mm(kMinDrumGrains * m.psd->d50) +
                                        ", psd.d50 of material " + m.name + "), got " + mm(d.diameter)});
  return problems;
}

}  // namespace feedflow
