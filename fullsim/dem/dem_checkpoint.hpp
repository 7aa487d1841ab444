#pragma once
// A DEM checkpoint: everything a run needs to continue bit-identically, in one self-describing
// HDF5 file (format name and version on the root, units on every dataset and quantity):
// the particles in their current slot order (with forces, torques and wall-contact history),
// the neighbour list as it stands (entries, id pairs, contact history, positions at the last
// rebuild, rebuild counter that schedules the Morton re-sort), the walls' current pose,
// motion and contact set, the outlet sink's booked mass and events, the box, the step, the time,
// the time step and the blow-up guard's energy book (with the wall speed its floor allows for).
// Written whole or not at all (a temporary beside the target, renamed over it). A file of another
// format or version, a truncated or inconsistent one is refused with a std::runtime_error naming
// the file and what is wrong.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "fullsim/dem/neighbour_list.hpp"
#include "fullsim/dem/outlet_sink.hpp"
#include "fullsim/dem/particle_store.hpp"
#include "fullsim/dem/simulation_box.hpp"
#include "fullsim/dem/wall.hpp"

namespace feedflow {

// Version 2: the guard's book holds the wall speed its floor allows for (/guard wall_speed).
// Version 3: each analytic wall names its contact set (/walls/NNNN contact_set).
constexpr std::int64_t kDemCheckpointVersion = 3;
inline constexpr const char* kDemCheckpointFormat = "feedflow DEM checkpoint";

struct DemCheckpoint {
  long step = 0;
  double time = 0.0;             // [s]
  double time_step = 0.0;        // [s]
  double particle_steps = 0.0;
  std::string contact_law;       // the effective law's name (must match on restore)
  Vec3 gravity = Vec3::Zero();   // [m/s^2]
  SimulationBox box;
  ParticleStore particles;
  NeighbourList neighbours;
  std::vector<Wall> walls;
  std::optional<OutletSink> sink;
  double guard_initial_energy = 0.0;  // [J]
  double guard_energy_floor = 0.0;    // [J]
  double guard_gravity_work = 0.0;    // [J]
  double guard_wall_speed = 0.0;      // [m/s] the floor allows for (0: set with still walls)
};

class Hdf5File;

void write_dem_checkpoint(const std::filesystem::path& path, const DemCheckpoint& checkpoint);
DemCheckpoint read_dem_checkpoint(const std::filesystem::path& path);
// The same into and from an open file (a scene run's checkpoint, with its /scene group beside).
void write_dem_checkpoint(Hdf5File& file, const DemCheckpoint& checkpoint);
DemCheckpoint read_dem_checkpoint(const Hdf5File& file);

}  // namespace feedflow
