#include "models/hopper/bulk_density_models.hpp"

#include "models/core/errors.hpp"

namespace feedflow {
namespace {

using Compressibility = std::optional<BulkCompressibility>;

HopperDensity constant(const Material& m, const Compressibility&) {
  return {BulkDensity::constant(m.bulk.density), "constant design bulk density"};
}

HopperDensity table(const Material& m, const Compressibility&) {
  if (m.flow->density.empty())
    throw InputError("--model", "hopper.bulk_density",
                     "table chosen, but material " + m.name + " has no density_major_stress/density table in "
                     "[flow_properties]");
  return {BulkDensity::tabulated(m.flow->density_major_stress, m.flow->density),
          "measured compressibility table rho_b(sigma1)"};
}

// Without hypoplastic parameters: the measured table, else the design density; the model text
// says why.
HopperDensity compressible(const Material& m, const Compressibility& c) {
  if (c)
    return {BulkDensity::compressible(*c),
            "critical-state density from the Bauer compression law (hypoplastic parameters), anchored on the " +
                c->anchor()};
  HopperDensity d = m.flow->density.empty() ? constant(m, c) : table(m, c);
  d.model += " (the stress-dependent default needs [hypoplastic] parameters, which " + m.name + " lacks)";
  return d;
}

constexpr HopperDensityModel kDensityRows[] = {
    {{"compressible", Rung::L0,
      "rho_b at the local stress, Bauer law (without hypoplastic parameters: the table, else "
      "constant)"},
     &compressible},
    {{"table", Rung::L0, "the measured compressibility table rho_b(sigma1) of [flow_properties]"},
     &table},
    {{"constant", Rung::L0, "the constant design bulk density"}, &constant},
};

constexpr ModelTable<HopperDensityModel> kDensityTable{"hopper.bulk_density", "bulk density",
                                                       kDensityRows};

}  // namespace

const ModelTable<HopperDensityModel>& hopper_density_models() { return kDensityTable; }

}  // namespace feedflow
