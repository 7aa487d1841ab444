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
// Filling by rain-fall with the scene kit (rain_fill.hpp), as the seed did (3.2.1: "the same
// rainfall procedure as described in Section 3.1"): spheres shot normal to the ramp from a
// region over the whole bin that rides a few radii above the resting fill (so the drift down
// the slope while falling stays below a radius), at a rate raising the bed by ~0.1 m/s,
// until 20 % more than the fill's mass (packing 0.6) is in; settled against the closed gate
// until the largest speed is below `settle_speed` (seed: 1 mm/s); centres above the fill height
// removed.
#include <memory>
#include <optional>
#include <ostream>

#include "fullsim/dem/dem_engine.hpp"
#include "fullsim/dem/scene/deposit_profile.hpp"
#include "fullsim/dem/scene/rain_fill.hpp"

namespace feedflow {

struct InclinedPlaneSpec {
  double angle = 0.0;          // ramp inclination [rad]
  double ramp_length = 3.0;    // [m] from the gate to the ramp's end
  double bin_length = 0.57;    // [m] along the slope
  double bin_height = 0.915;   // [m]
  double fill_height = 0.5;    // [m] normal to the ramp
  double gate_opening = 0.35;  // [m]
  double slab_depth = 0.015;   // [m] periodic, across the ramp
  unsigned seed = 1;               // of the rain's random positions
  double settle_speed = 1e-3;     // [m/s] settled when the largest speed is below (seed)
  double max_settle_time = 3.0;   // [s] of settling at most
};

class InclinedPlaneScene {
 public:
  // `settings.gravity` is replaced by the tilted gravity.
  InclinedPlaneScene(DemSettings settings, InclinedPlaneSpec spec);
  // A run restored from a checkpoint of this scene (the meshes are rebuilt from the spec).
  InclinedPlaneScene(DemSettings settings, InclinedPlaneSpec spec, DemCheckpoint checkpoint);

  // The rain-fall settings of this bin (region over the bin, following the fill; trim at the
  // fill height).
  RainFillSettings rain() const;
  // Rain-fall, settling, trimming (logs each phase), or the rest of a fill restored by
  // restore_fill(). Returns the fill's report; `interrupted` when Ctrl-C stopped it.
  const FillReport& fill(std::ostream& log, ProgressSink* progress = nullptr);
  // A fill stopped by Ctrl-C: its checkpoint into `file` (false: nothing to continue from, the
  // first batch was not in); restore_fill() reads it into a scene built from the same spec.
  bool save_fill(Hdf5File& file) const;
  void restore_fill(const Hdf5File& file);
  const FillReport& fill_report() const { return fill_report_; }
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

  DemSettings settings_;
  InclinedPlaneSpec spec_;
  std::unique_ptr<DemEngine> engine_;
  double release_time_ = 0.0;
  std::optional<RainFill> rain_fill_;  // the fill under way or done
  FillReport fill_report_;
};

}  // namespace feedflow
