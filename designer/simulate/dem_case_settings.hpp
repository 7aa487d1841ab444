#pragma once
// The DEM settings of a case for `feedflow simulate`: the material's Table 2 sets, the normal
// law chosen by [dem] normal_law (+ history + cdt, the seed's composition), the time step of [dem]
// time_step (below the stable one: warned; above it: refused by the engine unless [dem]
// force_time_step = yes).
#include <string>
#include <vector>

#include "designer/case/case.hpp"
#include "fullsim/dem/dem_engine.hpp"
#include "fullsim/dem/scene/slab_faces.hpp"

namespace feedflow {

// The run shared among `ranks`. Throws InputError naming the material when it has no [dem]
// parameters.
DemSettings dem_case_settings(const Case& c, const DemRanks& ranks = DemRanks::one());

// Throws InputError naming dem.slab_depth when a periodic slab is thinner than two neighbour
// cutoffs of the settings' particles (a particle would meet its own image).
void require_slab_depth(const Case& c, const DemSettings& settings, double slab_depth);

// The engine's warning on its time step (a step forced above the stable one, or far below it),
// added to a record's assumptions; nothing when the step is the stable one.
void add_time_step_warning(const DemEngine& engine, std::vector<std::string>& assumptions);

// The case's [dem] slab_faces (automatic when absent).
SlabFaces slab_faces_of(const Case& c);
// For a scene whose slab is periodic only (drum, chute): throws InputError naming
// dem.slab_faces when the case asks for frictional or frictionless faces.
void require_periodic_faces(const Case& c, const std::string& scene);

// The time between particle snapshots of a DEM scene run [s]: the case's [dem]
// snapshot_interval, or by default the shortest of 1, 2, 5, 10, 20, 50, ... sample intervals
// (`sample_interval` [s], the rows of timeseries.csv) that gives at most 50 snapshots over the
// planned run (`duration` [s] after the scene's origin): 20 to 50 frames, enough to follow the
// flow in ParaView without filling the disk (~100 bytes a particle a snapshot), each on a row's
// step; a run of fewer than 50 rows has a snapshot at every row.
double dem_snapshot_interval(const Case& c, double duration, double sample_interval);

}  // namespace feedflow
