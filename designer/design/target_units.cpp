#include "designer/design/target_units.hpp"

#include "models/units/quantity_parser.hpp"

namespace feedflow {

void show_in_target_units(const Case& c, Estimates& results) {
  for (const auto& [key, unit] : c.written_units) {
    if (!key.starts_with("design.")) continue;
    Dimension target;
    try {
      target = parse_unit(unit).dimension;
    } catch (const UnitError&) {
      continue;
    }
    if (target == dim::dimensionless) continue;
    for (auto& [name, e] : results) {
      if (!e.is_number() || e.unit.empty()) continue;
      try {
        if (parse_unit(e.unit).dimension == target) e.display_unit = unit == e.unit ? "" : unit;
      } catch (const UnitError&) {  // a unit the parser does not know: left as it is
      }
    }
  }
}

}  // namespace feedflow
