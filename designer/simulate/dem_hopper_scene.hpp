#pragma once
// The DEM hopper scene of a case: a wedge hopper as a slab (the seed's pilot hopper as one
// layer; fullsim/dem/scene/wedge_hopper_slab.hpp) or a conical hopper in 3D, whole or a sector
// (conical_hopper.hpp), with the case's semi-angle, outlet, bin, fill height and material,
// rain-filled, settled, trimmed at H and layer-banded, then the gate opened; or the same scene
// restored from a checkpoint (the fill skipped).
#include <cstdint>
#include <optional>
#include <ostream>
#include <string>
#include <variant>
#include <vector>

#include "designer/case/case.hpp"
#include "fullsim/common/hdf5_file.hpp"
#include "fullsim/dem/dem_engine.hpp"
#include "fullsim/dem/scene/conical_hopper.hpp"
#include "fullsim/dem/scene/rain_fill.hpp"
#include "fullsim/dem/scene/speed_profile.hpp"
#include "fullsim/dem/scene/wedge_hopper_slab.hpp"

namespace feedflow {

struct DemHopperScene {
  std::variant<WedgeHopperSlab, ConicalHopper> geometry;
  DemSettings settings;
  double density = 0.0;        // of the spheres [kg/m^3]
  double slot_length = 0.0;    // a wedge's real out-of-plane length [m]
  int bands = 10;              // initial-height bands for the flow pattern
  std::uint64_t seed = 1;
  double default_duration = 20.0;  // [s] after the opening when neither --time nor [dem] says

  // Known once filled (or restored):
  double opening_time = 0.0;   // [s] the gate is removed
  long opening_step = 0;
  FillReport fill;             // counts and masses of the fill (a restored run: those saved)
  std::optional<RainFill> rain_fill;  // the fill under way (stopped by Ctrl-C) or done

  const WedgeHopperSlab* slab() const { return std::get_if<WedgeHopperSlab>(&geometry); }
  // Masses of the simulated part to the real hopper: slot length / slab depth, or 360 deg over
  // the sector.
  double scale() const;
  double radius() const;             // of the spheres [m]
  double outlet_size() const;        // W or D [m]
  double transition_height() const;  // the converging section's top above the outlet [m]
  // The simulated part's volume below the fill's trim height [m^3] (its fill over it: the bed's
  // bulk density).
  double filled_volume() const;
  // The free-fall rate scale of the simulated part's outlet (rho W sqrt(g W) per slab depth,
  // rho pi/4 D^2 sqrt(g D) per sector share) [kg/s].
  double outlet_rate_scale(double bulk_density) const;
  ProfileOffset profile_offset() const;  // across x (wedge) or from the axis (cone)
  SimulationBox box() const;
  void add_walls(DemEngine& engine) const;
  RainFillSettings rain() const;
  std::string describe() const;
  // "DEM slab 3 mm deep ..., scaled x 166.7 (...)" or "DEM cone, whole/sector ...", for results.
  std::string model_text() const;
};

// Reads the scene from the case (wedge hopper, material with DEM parameters, [dem] table).
// Throws InputError naming the key for a case the scene cannot build.
DemHopperScene hopper_scene_from_case(const Case& c);

// The engine with the slab's walls, wedge mesh and sink, and no particles (a restart restores
// them from the checkpoint).
DemEngine hopper_scene_structure(const DemHopperScene& scene);
// A new run: the structure rain-filled, settled and trimmed (or the rest of a fill restored by
// restore_hopper_fill), and the gate opened (at the settled time). False when Ctrl-C stopped
// the fill.
bool fill_hopper_scene(DemHopperScene& scene, DemEngine& engine, ProgressSink* progress, std::ostream& log);
// A fill stopped by Ctrl-C: its checkpoint into `file` (false: nothing to continue from), and
// back into a scene and an engine built from the same case.
bool save_hopper_fill(const DemHopperScene& scene, const DemEngine& engine, Hdf5File& file);
void restore_hopper_fill(DemHopperScene& scene, DemEngine& engine, const Hdf5File& file);
// The scene's plan lines.
void describe_hopper_scene(const DemHopperScene& scene, std::ostream& log);

// The scene's data into a checkpoint's /scene group, and back.
void save_hopper_scene(const DemHopperScene& scene, Hdf5File& checkpoint);
void restore_hopper_scene(DemHopperScene& scene, const Hdf5File& checkpoint);

}  // namespace feedflow
