#pragma once
// The contact forces of one step, behind one virtual call per phase: make_force_kernel() turns
// the run-time law choice into a LawForces<Law> (law_forces.hpp), whose pair and wall loops are
// compiled once per composed law, so the loops themselves never dispatch.
#include <cstddef>
#include <memory>
#include <string>
#include <vector>

#include "fullsim/dem/mesh_wall.hpp"
#include "fullsim/dem/neighbour_list.hpp"
#include "fullsim/dem/particle_store.hpp"
#include "fullsim/dem/simulation_box.hpp"
#include "fullsim/dem/wall.hpp"
#include "models/contact/contact_law_registry.hpp"
#include "models/material/dem_parameters.hpp"

namespace feedflow {

// What the force loops read and add to.
struct ForceContext {
  ParticleStore& particles;
  NeighbourList& neighbours;
  const SimulationBox& box;
  const std::vector<Wall>& walls;
  const std::vector<MeshWall>& meshes;
  double time = 0.0;  // [s]
  double dt = 0.0;    // [s]
  bool parallel = true;  // run the loops on the OpenMP threads (off for small systems)
  int max_lane_bits = 512;  // widest vector lanes of the pair loop to use, where available
  // Per particle slot, the walls it can touch (wall_reach.hpp); null: every wall is tested.
  const std::uint64_t* wall_reach = nullptr;
  // The slots of this rank's own particles (the ghosts behind them touch no wall here: their
  // own rank adds their wall forces).
  std::size_t owned = static_cast<std::size_t>(-1);
};

// The widest vector lanes of the pair loop this processor runs: 512 (AVX-512 F, VL, DQ), 256
// (AVX2 and FMA) or 128 (any x86-64); looked up once. All give the same bits.
int lane_bits_available();

// The deepest contact seen by a loop: overlap over the smaller radius.
struct DeepestOverlap {
  double ratio = 0.0;
  std::size_t slot = 0;  // the particle (body i of the pair)
  bool with_wall = false;
};

class ForceKernel {
 public:
  virtual ~ForceKernel() = default;
  virtual std::string name() const = 0;
  // Doubles of history per contact (pair entry or particle-wall pair).
  virtual std::size_t history_size() const = 0;
  // Adds the particle-particle forces and torques of the neighbour list and the particle-wall
  // ones (P-W parameter set) in one parallel region; `wall_seconds` is the time one thread spent
  // on its wall contacts [s].
  virtual void add_contact_forces(ForceContext& c, DeepestOverlap& pairs, DeepestOverlap& walls,
                                  double& wall_seconds) = 0;
};

std::unique_ptr<ForceKernel> make_force_kernel(const ContactLawChoice& choice,
                                               const DemParameters& dem);

// make_force_kernel() for the laws whose normal part is NormalParts' part I (choice.normal is not
// read). Defined in law_forces.hpp and compiled in force_kernel_normal_<I>.cpp, one file per
// normal part, so that a build spreads the compositions over its cores.
template <std::size_t I>
std::unique_ptr<ForceKernel> make_force_kernel_of_normal(const ContactLawChoice& choice,
                                                         const DemParameters& dem);

}  // namespace feedflow
