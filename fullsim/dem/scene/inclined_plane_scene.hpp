#pragma once
// The inclined-plane scene (seed section 3.2, data.md 3), in the ramp's frame: x down the
// slope from the gate, z normal to the ramp, y across it; gravity tilted by the ramp angle,
// g (sin eta, 0, -cos eta), so every wall is axis-aligned. A periodic slab across the ramp
// (the seed's 15 mm, five diameters; lateral spill cannot be shown). Assumed (the seed gives no
// drawing): the storage bin stands on the upper end of the ramp with its walls normal to it;
// its floor is flat (the plane z = 0, Table 2 P-W friction), its back wall a plane at
// x = -bin_length, its gate a plane at x = 0 that is removed on release while a plate from the
// gate opening upwards stays (the gate "lifted to the opening", a two-triangle mesh).
// The ramp (x >= 0) is made no-slip as the seed's glued chips did, by geometry rather than by
// friction: a saw-tooth mesh of 45 deg faces, one particle diameter in period and one radius
// high. A sphere resting in a groove cannot slide without climbing a 45 deg face, which needs
// a tangential/normal force ratio above tan(45 deg + atan 0.2) = 1.5, while the flow at 29.5 to
// 37 deg drives at most tan 37 = 0.75; a high wall friction would also roughen the bin's walls
// (one P-W set serves every wall). Particles leaving the ramp's end are removed (outlet sink).
// Filling: a jittered lattice in the bin, settled against the closed gate under the tilted
// gravity, trimmed above the fill height, settled again.
#include <memory>
#include <ostream>

#include "fullsim/dem/dem_engine.hpp"
#include "fullsim/dem/scene/deposit_profile.hpp"

namespace feedflow {

struct InclinedPlaneSpec {
  double angle = 0.0;          // ramp inclination [rad]
  double ramp_length = 3.0;    // [m] from the gate to the ramp's end
  double bin_length = 0.57;    // [m] along the slope
  double bin_height = 0.915;   // [m]
  double fill_height = 0.5;    // [m] normal to the ramp
  double gate_opening = 0.35;  // [m]
  double slab_depth = 0.015;   // [m] periodic, across the ramp
  unsigned seed = 1;
  double settle_speed = 0.05;     // [m/s]
  double max_settle_time = 3.0;   // [s] per settling phase
};

class InclinedPlaneScene {
 public:
  // `settings.gravity` is replaced by the tilted gravity.
  InclinedPlaneScene(DemSettings settings, InclinedPlaneSpec spec);
  // A run restored from a checkpoint of this scene (the meshes are rebuilt from the spec).
  InclinedPlaneScene(DemSettings settings, InclinedPlaneSpec spec, DemCheckpoint checkpoint);

  void fill(std::ostream& log);
  void open_gate(std::ostream& log);  // the sampling clock starts
  // True once the kinetic energy per particle is below 1e-3 m g d (a particle of the bed moving
  // at about 1 % of sqrt(g d)): the flow has clearly stopped.
  bool flow_stopped() const;
  DepositProfile deposit() const;  // bins of one particle diameter

  DemEngine& engine() { return *engine_; }
  const DemEngine& engine() const { return *engine_; }
  const InclinedPlaneSpec& spec() const { return spec_; }
  double release_time() const { return release_time_; }
  double ramp_surface() const;  // z of the teeth's crests [m]
  const DemSettings& settings() const { return settings_; }

 private:
  void add_meshes(DemEngine& engine) const;
  void rebuild(DemCheckpoint checkpoint);
  void settle(std::ostream& log, const char* phase);

  DemSettings settings_;
  InclinedPlaneSpec spec_;
  std::unique_ptr<DemEngine> engine_;
  double release_time_ = 0.0;
};

}  // namespace feedflow
