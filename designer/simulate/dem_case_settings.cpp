#include "designer/simulate/dem_case_settings.hpp"

#include "models/core/errors.hpp"

namespace feedflow {

DemSettings dem_case_settings(const Case& c) {
  if (!c.material.dem)
    throw InputError(c.file, "material", "material " + c.material.name +
                                             " has no [dem] parameters (seed Table 2); the DEM needs them");
  DemSettings s;
  s.material = *c.material.dem;
  s.law = choose_contact_law(c.dem.normal_law);
  if (c.dem.time_step) s.requested_time_step = *c.dem.time_step;
  return s;
}

}  // namespace feedflow
