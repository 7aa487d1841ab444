#include "designer/case/simulation_settings.hpp"

#include "fullsim/dem/scene/slab_faces.hpp"
#include "models/contact/contact_law_registry.hpp"

namespace feedflow {

namespace {
constexpr std::string_view kRemapOrders[] = {"first",           "second",
                                             "second_stress",   "second_void_ratio",
                                             "second_density",  "second_momentum"};
constexpr std::string_view kMaterialFluxes[] = {"donor_cell", "limited", "plic"};
constexpr std::string_view kMixedCellRules[] = {"equal_strain_rate", "void_first"};
constexpr std::string_view kHopperSections[] = {"half", "full"};
constexpr std::string_view kWallCells[] = {"staircase", "cut"};
constexpr std::string_view kYesNo[] = {"no", "yes"};
// Simulated times and intervals: up to an hour (a DEM second takes minutes to hours).
constexpr Range kTimeRange{0.0, 3600.0, false, true};
}  // namespace

std::span<const FieldSpec<DemCaseSettings>> dem_case_fields() {
  using S = DemCaseSettings;
  static const FieldSpec<S> fields[] = {
      optional_number_field<S>(
          "slab_depth", &S::slab_depth, dim::length, "mm", Range{0.0, 1.0, false, true},
          "depth of the periodic slab (hopper 3 mm, chute 15 mm; drum: full length)"),
      optional_number_field<S>(
          "sector_angle", &S::sector_angle, dim::angle, "deg", Range{0.0, 6.2832, false, false},
          "a conical hopper's sector between frictionless symmetry planes (at most 90 deg; "
          "default 360 deg: the whole cone)"),
      optional_number_field<S>(
          "stopping_layer", &S::stopping_layer, dim::length, "mm", Range{0.0, 1.0, false, true},
          "a chute's DEM run as a periodic layer of this thickness on the ramp, set flowing "
          "and tilted to the chute's angle, that comes to rest or flows on (Pouliquen's "
          "h_stop; design --verify dem bisects it) instead of the bin released down the ramp"),
      optional_number_field<S>(
          "stopping_layer_length", &S::stopping_layer_length, dim::length, "mm",
          Range{0.0, 1.0, false, true},
          "a stopping layer's periodic length down the slope, in whole saw teeth (default 20 "
          "sphere diameters; a layer about as thick as its box may be held by it)"),
      optional_number_field<S>(
          "end_time", &S::end_time, dim::time, "s", kTimeRange,
          "simulated time after filling (default: until converged or stopped; a stopping "
          "layer: at rest, run away, steady from 4 s after the tilt on, or at most 10 s, or this)"),
      optional_number_field<S>("snapshot_interval", &S::snapshot_interval, dim::time, "s",
                               kTimeRange, "time between particle snapshots"),
      optional_number_field<S>("time_step", &S::time_step, dim::time, "us",
                               Range{0.0, 1.0, false, true},
                               "time step instead of the stable one (smaller: warned)"),
      optional_number_field<S>(
          "time_step_safety", &S::time_step_safety, dim::dimensionless, "-",
          Range{0.0, 1.0, false, true},
          "fraction of the stable step (models.md 5.1: 20 steps per period of the "
          "stiffest spring, 0.2 Rayleigh and Hertz times); above 1 the contacts are "
          "not resolved"),
      whole_number(optional_number_field<S>("random_seed", &S::random_seed, dim::dimensionless, "-",
                                            Range::closed(0.0, 4294967295.0),
                                            "seed of the rain-fall insertion (a whole number)")),
      label_field<S>("normal_law", &S::normal_law, NormalParts::kKeywords,
                     "normal contact law (default the seed's hysteretic_nonlinear2; hertz allows "
                     "a ~20x larger time step for reduced test twins)",
                     Presence::optional),
      label_field<S>("cohesion", &S::cohesion, CohesionParts::kKeywords,
                     "none (default: the normal force clipped at zero, as the seed's software) "
                     "or k_nc (the hysteretic law's -K_nc A2 delta branch of seed Eq. 7 pulls; "
                     "hysteretic laws only)",
                     Presence::optional),
      label_field<S>("force_time_step", &S::force_time_step, kYesNo,
                     "yes: take time_step even above the stable step (e.g. the seed's 1 us, 15 "
                     "steps per period of the stiffest spring instead of 20); the blow-up guard "
                     "watches the run (default no: refused)",
                     Presence::optional),
      label_field<S>("slab_faces", &S::slab_faces, slab_face_keywords(),
                     "front and back faces of a DEM slab: frictional (the particle-wall set), "
                     "frictionless (no sliding or rolling resistance) or periodic (at least two "
                     "neighbour cutoffs deep); default periodic when deep enough, else "
                     "frictional (drum and chute slabs are periodic only)",
                     Presence::optional),
  };
  return fields;
}

std::span<const FieldSpec<CelCaseSettings>> cel_case_fields() {
  using S = CelCaseSettings;
  static const FieldSpec<S> fields[] = {
      optional_number_field<S>("cell_size", &S::cell_size, dim::length, "mm",
                               Range::closed(1e-3, 1.0), "edge of the square Eulerian cells"),
      optional_number_field<S>("end_time", &S::end_time, dim::time, "s", kTimeRange,
                               "simulated time after the gravity phase"),
      optional_number_field<S>("snapshot_interval", &S::snapshot_interval, dim::time, "s",
                               kTimeRange, "time between field snapshots"),
      optional_number_field<S>(
          "time_step_safety", &S::time_step_safety, dim::dimensionless, "-",
          Range{0.0, 1.0, false, true},
          "Courant number of the step (default 0.8): the step is this fraction of a "
          "cell crossed at the wave speed plus the flow speed; above 1 a wave "
          "crosses more than a cell per step"),
      label_field<S>("remap_order", &S::remap_order, kRemapOrders,
                     "advection in the remap: first (donor cell, default), second (van Leer "
                     "MUSCL on stress, void ratio, density and nodal momentum), or second "
                     "order on one quantity only (second_stress, second_void_ratio, "
                     "second_density, second_momentum)",
                     Presence::optional),
      label_field<S>("material_flux", &S::material_flux, kMaterialFluxes,
                     "material volume through the faces: donor_cell (default; the drum: "
                     "plic), limited (van Leer MUSCL volume fraction) or plic (Youngs "
                     "interface in mixed cells)",
                     Presence::optional),
      label_field<S>("mixed_cells", &S::mixed_cells, kMixedCellRules,
                     "strain rate of the material in cells part filled with void: "
                     "equal_strain_rate (the cell's, default) or void_first (the void takes "
                     "the volume change, the material the shear)",
                     Presence::optional),
      label_field<S>("hopper_section", &S::hopper_section, kHopperSections,
                     "section of a wedge hopper: half (the seed's half slice with a symmetry "
                     "plane at the centre, default) or full (the full width, both walls)",
                     Presence::optional),
      label_field<S>("wall_cells", &S::wall_cells, kWallCells,
                     "how inclined walls cut the grid: staircase (cells whose centre lies in a "
                     "wall are shut, default) or cut (every cell and face open by the share on "
                     "the material side)",
                     Presence::optional),
  };
  return fields;
}

}  // namespace feedflow
