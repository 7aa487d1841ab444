#pragma once
// A CEL scene as the seed ran its FEM models (data.md 2.2, models.md 5.2): the grid, the solver
// options (box faces, rigid walls, gravity), the material blocks, a gravity phase that brings
// the material to rest (gravity ramped by a smooth step, dynamic relaxation, ended when the
// kinetic energy is small), then the event (outlet opened, gate lifted, drum started) and the
// plan lines that say what is on and what is left out. The scene builders (hopper_scene,
// drum_scene, chute_scene) make one from a case's equipment.
#include <cstddef>
#include <limits>
#include <string>
#include <vector>

#include "fullsim/cel/cel_solver.hpp"

namespace feedflow::cel {

struct GravityPhase {
  double ramp_time = 0.5;          // smooth step 0 -> g over this time [s]
  double settling_damping = 100.0;  // mass-proportional damping during the phase only [1/s]
  double kinetic_energy_ratio = 1e-3;  // ends after the ramp when KE < ratio x its peak
  double min_time = 0.6;           // [s]
  double max_time = 2.0;           // the seed deck's gravity step [s]
};

struct SceneEvent {
  std::string description;                 // "outlet gate removed"
  std::vector<std::size_t> walls_removed;  // indices into CelOptions::rigid_walls
  std::vector<std::size_t> walls_started;  // start moving at the event
  double motion_duration = std::numeric_limits<double>::infinity();  // then rest again [s]
  bool frame_started = false;  // the solver turns to CelOptions::frame (a drum)
};

// The material of a scene: bulk density and void ratio of the fill, initial stress -10 Pa I
// (seed deck).
struct SceneMaterial {
  double bulk_density = 0.0;  // [kg/m^3]
  double void_ratio = 0.0;    // [-]
};

struct CelScene {
  std::string name;
  CelGrid grid;
  CelOptions options;
  std::vector<MaterialBlock> material;
  GravityPhase gravity;
  SceneEvent event;
  double event_duration = 1.0;     // default simulated time after the event [s]
  double section_depth_factor = 1.0;  // full section / simulated section (2 for a half slice)
  std::vector<std::string> plan;   // what is on and what is left out, one line each
};

// "h = 10 mm, 30 x 72 cells (0.30 m x 0.72 m)"
std::string grid_text(const CelGrid& grid);

}  // namespace feedflow::cel
