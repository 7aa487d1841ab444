#include "designer/equipment/equipment_registry.hpp"

#include <array>
#include <stdexcept>

#include "designer/design/chute_check.hpp"
#include "designer/design/drum_check.hpp"
#include "designer/design/hopper_check.hpp"
#include "designer/design/judge.hpp"
#include "designer/simulate/cel_chute_adapter.hpp"
#include "designer/simulate/cel_drum_adapter.hpp"
#include "designer/simulate/cel_hopper_adapter.hpp"
#include "designer/simulate/dem_chute_adapter.hpp"
#include "designer/simulate/dem_drum_adapter.hpp"
#include "designer/simulate/dem_hopper_adapter.hpp"

namespace feedflow {
namespace {

const std::array kEquipment{
    EquipmentEntry{EquipmentKind::hopper,
                   [](const Case& c, const ModelChoices& m, DesignDetail d, DesignRecord& r) {
                     check_hopper(c, std::get<Hopper>(c.equipment), m, d, r);
                   },
                   [](const Case& c, const Estimates& e) {
                     return judge_hopper(std::get<Hopper>(c.equipment), c.design, e);
                   },
                   dem_hopper_adapter, cel_hopper_adapter, Solver::cel,
                   "CEL-FEM chosen: the seed's rule puts pilot and industrial hoppers on the "
                   "continuum (same cost as a one-layer DEM slab, no slab scaling of the mass)"},
    EquipmentEntry{EquipmentKind::chute,
                   [](const Case& c, const ModelChoices& m, DesignDetail d, DesignRecord& r) {
                     check_chute(c, std::get<Chute>(c.equipment), m, d, r);
                   },
                   [](const Case& c, const Estimates& e) {
                     return judge_chute(std::get<Chute>(c.equipment), c.design, e);
                   },
                   dem_chute_adapter, cel_chute_adapter, Solver::cel,
                   "CEL-FEM chosen: the seed found the continuum about 40x cheaper than DEM on the "
                   "full-scale inclined plane"},
    EquipmentEntry{
        EquipmentKind::drum,
        [](const Case& c, const ModelChoices&, DesignDetail d, DesignRecord& r) {
          check_drum(c, std::get<Drum>(c.equipment), d, r);
        },
        [](const Case& c, const Estimates& e) {
          return judge_drum(std::get<Drum>(c.equipment), c.design, e);
        },
        dem_drum_adapter, cel_drum_adapter, Solver::dem,
        "DEM chosen: a laboratory drum is a small system, where the seed found particles "
        "as cheap as the continuum (about 2x) and closer to the experiment"},
};

}  // namespace

std::span<const EquipmentEntry> equipment_registry() { return kEquipment; }

const EquipmentEntry& equipment_of(EquipmentKind kind) {
  for (const auto& e : kEquipment)
    if (e.kind == kind) return e;
  throw std::logic_error("equipment kind without a registry row");
}

}  // namespace feedflow
