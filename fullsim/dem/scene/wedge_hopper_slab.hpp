#pragma once
// A wedge (plane-flow) hopper as a quasi-2D DEM slab (seed 3.1, data.md 2.1): x across, y
// through the slab, z up; the outlet (width W, centred on x = 0) lies in the plane z = 0. The
// inclined walls run from the outlet edges at the semi-angle theta (from the vertical) up to
// the bin width B, then the vertical bin walls rise to the top. The inclined walls are finite
// (mesh rectangles built here, so they do not close below the outlet); the bin walls are
// analytic planes (below the bin they lie outside the wedge, where no particle goes); the gate
// is an analytic plane over the outlet, removed at the opening time ("removing the lower wall
// sections"); the outlet sink takes every particle that has fallen 5 R below the outlet.
//
// Slab depth D and faces (slab_faces.hpp): by default frictional front and back planes at
// y = 0 and y = D when D < 2 x the neighbour cutoff, and a slab periodic in y from there on.
// For D = 2 R the centres are inserted in the mid-plane and the fill stays there, but once the
// layer flows it buckles out of it on round-off, so every grain soon presses on a face and the
// faces' friction acts (measured: tests/benchmarks/RECORD.md). The faces may be chosen
// instead: frictional or frictionless planes at any depth, periodic from two neighbour cutoffs
// on, or planar for one layer (no faces; DemEngine::hold_in_plane keeps every centre in the
// mid-plane).
#include <functional>
#include <string>

#include "fullsim/dem/dem_engine.hpp"
#include "fullsim/dem/scene/rain_fill.hpp"
#include "fullsim/dem/scene/slab_faces.hpp"

namespace feedflow {

struct WedgeHopperSlab {
  double semi_angle = 0.0;     // theta from the vertical [rad]
  double outlet_width = 0.0;   // W [m]
  double bin_width = 0.0;      // B [m]
  double fill_height = 0.0;    // H above the virtual apex [m]
  double depth = 0.0;          // D [m]
  double radius = 0.0;         // particle radius [m]
  double skin_fraction = 0.3;  // of the engine (decides whether the slab can be periodic)
  SlabFaces faces = SlabFaces::automatic;  // front and back faces

  double apex_depth() const;   // the virtual apex below the outlet plane [m]
  double bin_bottom() const;   // height of the wedge-bin transition above the outlet [m]
  double fill_top() const;     // height of the fill surface above the outlet (H - apex) [m]
  double half_width(double z) const;  // of the container at height z [m]
  bool periodic() const;  // a periodic slab (chosen, or automatic and D >= 2 x the cutoff)
  bool one_layer() const;  // D < 2 R x 1.001: the centres in the mid-plane
  // The faces as built: frictional, frictionless, periodic or planar (automatic resolved).
  SlabFaces built_faces() const;
  std::string describe_faces() const;  // what the faces are and what they carry, for plans
  double sink_height() const { return -5.0 * radius; }
  double wall_top() const;     // the bin walls reach this high (room for the rain) [m]
  SimulationBox box() const;
  // The walls (named "wedge", "bin left/right", "front", "back", "gate") and the sink; the
  // front and back take the frictionless contact set for frictionless faces, and a planar
  // layer has none (the engine holds it in the mid-plane).
  void add_walls(DemEngine& engine) const;
  // The inclined and bin walls in the slab's mid-plane, for pictures (the gate left out).
  SceneOutline outline() const;
  // The inclined walls alone (a restored run gets its analytic walls and sink from the
  // checkpoint, which does not hold meshes).
  MeshWall wedge_mesh() const;
  // Centres at least R inside the container and above the gate.
  std::function<bool(const Vec3&, double)> admits() const;
  // The rain-fall settings of this hopper (region over the bin, following the fill; stop
  // at the fill top + 4 R; trim at the fill top; `bands` equal bands from the outlet plane).
  RainFillSettings rain(double density, int bands, std::uint64_t seed) const;
  // Mass of the fill for a solid volume fraction `phi` [kg] (the slab's share).
  double fill_mass(double density, double phi) const;
  std::string describe() const;
  // Throws InputError naming the key for impossible geometry.
  void check() const;
};

}  // namespace feedflow
