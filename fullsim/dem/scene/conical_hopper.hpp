#pragma once
// A conical hopper in 3D, whole or a sector of it (issue 22): z up along the axis, the
// circular outlet (diameter D, centred on the axis) in the plane z = 0. The cone wall runs
// from the outlet rim at the semi-angle theta (from the vertical) up to the bin diameter B, then
// the cylindrical bin rises to the top. The cone is a finite triangle mesh built here (fine
// enough that its facets stand less than R/20 off the true cone, and it does not close below
// the outlet); the bin is an analytic cylinder (below the transition it lies outside the cone,
// where no particle goes); the gate is an analytic plane over the outlet, removed at the
// opening; the outlet sink takes every particle that has fallen 5 R below the outlet.
//
// A sector of angle alpha (at most 90 deg, or the whole 360 deg) is bounded by two planes
// through the axis with the frictionless contact set: symmetry planes, on which a grain of the
// whole hopper would feel its mirror image's push but no friction. The sector spans azimuths
// -alpha/2 .. alpha/2 about +x; masses scale by 360 deg / alpha to the whole hopper. Near the
// axis the sector is narrower than a grain; the outlet's own radius keeps that corner small.
#include <cstdint>
#include <functional>
#include <string>

#include "fullsim/dem/dem_engine.hpp"
#include "fullsim/dem/scene/rain_fill.hpp"

namespace feedflow {

struct ConicalHopper {
  double semi_angle = 0.0;       // theta from the vertical [rad]
  double outlet_diameter = 0.0;  // D [m]
  double bin_diameter = 0.0;     // B [m]
  double fill_height = 0.0;      // H above the virtual apex [m]
  double sector = 0.0;           // alpha [rad]: 2 pi for the whole hopper
  double radius = 0.0;           // particle radius [m]

  bool whole() const;
  double share() const;         // alpha / 2 pi: the simulated part of the hopper
  double apex_depth() const;    // the virtual apex below the outlet plane [m]
  double bin_bottom() const;    // height of the cone-bin transition above the outlet [m]
  double fill_top() const;      // height of the fill surface above the outlet (H - apex) [m]
  double wall_top() const;      // the bin reaches this high (room for the rain) [m]
  double radius_at(double z) const;  // of the container at height z [m]
  double sink_height() const { return -5.0 * radius; }
  SimulationBox box() const;
  // The cone mesh ("cone"), the bin ("bin"), the sector's sides ("side a", "side b"), the
  // gate ("gate") and the sink.
  void add_walls(DemEngine& engine) const;
  MeshWall cone_mesh() const;
  // The walls in the sector's mid-plane (y = 0), for pictures.
  SceneOutline outline() const;
  // Centres at least R inside the cone, the bin and the sector, and above the gate.
  std::function<bool(const Vec3&, double)> admits() const;
  // The rain-fall settings (region over the bin's part of the sector, following the fill; trim
  // at the fill top; `bands` equal bands from the outlet plane).
  RainFillSettings rain(double density, int bands, std::uint64_t seed) const;
  // Mass of the fill for a solid volume fraction `phi`, the sector's share [kg].
  double fill_mass(double density, double phi) const;
  std::string describe() const;
  // What the run simulates, for result texts: "the whole cone" or "a 90 deg sector ...".
  std::string simulated_part() const;
  // Throws InputError naming the key for impossible geometry.
  void check() const;
};

}  // namespace feedflow
