#pragma once
// The rotating-drum scene (seed section 3.3, data.md 4): a drum of diameter D turning about the
// y axis (through the origin) as an analytic cylinder wall with the particle-wall set of Table 2;
// full 3D with its two end walls (length L), or a periodic axial slab of `slab_depth` without
// end walls (no end-wall friction: the angle comes out lower than in the full drum). Filled by
// rain-fall with the scene kit (rain_fill.hpp, seed 3.1.1; the seed's drum used "a random
// packing algorithm"): spheres dropped from a region inside the drum that rides a few radii
// above the resting fill, at a rate that raises the bed by ~0.1 m/s, until 20 % more than the
// fill's mass (packing 0.6) is in; settled until the largest speed is below `settle_speed`
// (seed: 1 mm/s), the particles above the fill line (the flat chord of the fill fraction f)
// removed; then the shell starts turning at `speed` (the bed was filled at rest).
//
//   DrumScene drum(settings, spec);
//   drum.fill(log);
//   drum.start_rotation(log);
//   while (...) { drum.engine().advance_to(t); watch.add(drum.sample()); }
#include <memory>
#include <optional>
#include <ostream>

#include "fullsim/common/drum_bed_regime.hpp"
#include "fullsim/dem/dem_engine.hpp"
#include "fullsim/dem/scene/drum_free_surface.hpp"
#include "fullsim/dem/scene/rain_fill.hpp"

namespace feedflow {

struct DrumSceneSpec {
  double diameter = 0.145;              // [m]
  double length = 0.202;                // [m] between the end walls (full 3D)
  double fill_fraction = 0.5;           // of the cross-section [-]
  double speed = 0.0;                   // [rad/s], about +y
  std::optional<double> slab_depth;     // [m] periodic slab along the axis; none: full 3D
  unsigned seed = 1;                    // of the rain's random positions
  double settle_speed = 1e-3;           // [m/s] settled when the largest speed is below (seed)
  double max_settle_time = 3.0;         // [s] of settling at most
};

// One measurement of the turning bed.
struct DrumSample {
  double time = 0.0;          // [s] since the shell started turning
  bool valid = false;         // a surface line could be fitted
  double angle = 0.0;         // dynamic angle of repose [rad] (surface raised on the side the
                              // shell carries the bed to: positive)
  DrumBedState state;         // angle_swing is 0 for a single sample
  std::vector<SurfacePoint> surface;  // the surface points (column centres, heights) [m]
  double kinetic_energy = 0.0;  // [J]
};

class DrumScene {
 public:
  DrumScene(DemSettings settings, DrumSceneSpec spec);
  // A run restored from a checkpoint of this scene (taken while turning or settling).
  DrumScene(DemSettings settings, DrumSceneSpec spec, DemCheckpoint checkpoint);

  // The rain-fall settings of this drum (region inside the drum, following the fill; trim at
  // the fill line).
  RainFillSettings rain() const;
  // Rain-fall, settling, trimming to the fill line (logs each phase), or the rest of a fill
  // restored by restore_fill(). Returns the fill's report; `interrupted` when Ctrl-C stopped it.
  const FillReport& fill(std::ostream& log, ProgressSink* progress = nullptr);
  // A fill stopped by Ctrl-C: its checkpoint into `file` (false: nothing to continue from, the
  // first batch was not in); restore_fill() reads it into a scene built from the same spec.
  bool save_fill(Hdf5File& file) const;
  void restore_fill(const Hdf5File& file);
  // The shell turns from now on; the sampling clock starts.
  void start_rotation(std::ostream& log);

  DrumSample sample() const;
  DemEngine& engine() { return *engine_; }
  const DemEngine& engine() const { return *engine_; }
  const DrumSceneSpec& spec() const { return spec_; }
  double rotation_start() const { return rotation_start_; }
  // A restored run's rotation start (saved beside its checkpoint) [s].
  void set_rotation_start(double t) { rotation_start_ = t; }
  double fill_line() const;  // z of the flat fill chord [m]
  double slab_depth() const;  // periodic depth or the full length [m]
  bool is_slab() const { return spec_.slab_depth.has_value(); }
  // Particles above the fill line removed after settling (0: the bed fell short of the fill
  // line, the fill fraction is lower than asked).
  std::size_t trimmed() const { return fill_report_.trimmed_count; }
  const FillReport& fill_report() const { return fill_report_; }

 private:
  SceneOutline shell_outline() const;  // the shell in the mid-plane, for pictures
  void rebuild(DemCheckpoint checkpoint);

  DemSettings settings_;
  DrumSceneSpec spec_;
  std::unique_ptr<DemEngine> engine_;
  double rotation_start_ = 0.0;
  std::optional<RainFill> rain_fill_;  // the fill under way or done
  FillReport fill_report_;
};

}  // namespace feedflow
