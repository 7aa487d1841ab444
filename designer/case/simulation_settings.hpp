#pragma once
// The optional [dem] and [cel] tables of a case file: how a full simulation of the case is
// run. Every field is optional; an absent one takes the scene's default (stated in its plan).
#include <optional>
#include <span>
#include <string>

#include "models/core/field_spec.hpp"

namespace feedflow {

struct DemCaseSettings {
  std::optional<double> slab_depth;         // [m] periodic slab depth; none: the scene's default
  std::optional<double> sector_angle;       // [rad] of a conical hopper simulated; none: whole
  std::optional<double> stopping_layer;     // [m] a chute's run as a periodic layer this thick
  std::optional<double> stopping_layer_length;  // [m] its periodic length down the slope
  std::optional<double> end_time;           // [s] simulated time after filling (--time wins)
  std::optional<double> snapshot_interval;  // [s] between HDF5 particle snapshots
  std::optional<double> time_step;          // [s] below the stable step (warned) or forced
  std::optional<double> time_step_safety;   // [-] fraction of the stable step, (0, 1]
  std::optional<double> random_seed;        // [-] of the rain-fall insertion
  std::string normal_law;                   // empty: the seed's (hysteretic_nonlinear2)
  std::string cohesion;                     // empty: none (the normal force clipped at zero)
  std::string force_time_step;              // "yes": time_step taken above the stable step
  std::string slab_faces;                   // empty: periodic when deep enough, else frictional
};

struct CelCaseSettings {
  std::optional<double> cell_size;          // [m] edge of the square Eulerian cells
  std::optional<double> end_time;           // [s] simulated time after the gravity phase
  std::optional<double> snapshot_interval;  // [s] between HDF5 field snapshots
  std::optional<double> time_step_safety;   // [-] Courant number of the step, (0, 1]
  std::string remap_order;                  // empty: first; second; second_<quantity>
  std::string material_flux;                // empty: donor_cell; limited; plic
  std::string mixed_cells;                  // empty: equal_strain_rate; void_first
  std::string hopper_section;               // empty: half; full
  std::string wall_cells;                   // empty: staircase; cut
};

std::span<const FieldSpec<DemCaseSettings>> dem_case_fields();
std::span<const FieldSpec<CelCaseSettings>> cel_case_fields();

}  // namespace feedflow
