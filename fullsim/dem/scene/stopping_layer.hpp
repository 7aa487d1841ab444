#pragma once
// Pouliquen's stopping thickness on the particle rung: a layer of the material on the seed's
// rough ramp (sawtooth_ramp.hpp), periodic down the slope and across it, so the layer has no
// front, no bin and no end (Pouliquen 1999 measured h_stop(angle) as the thickness a flow leaves
// when it stops; Silbert et al. 2001 found it so in DEM with a periodic layer). A layer thicker
// than h_stop(angle) keeps flowing, a thinner one comes to rest, so a bisection on the thickness
// at one angle brackets h_stop. The scene costs what the layer holds: about 1 100 of the seed's
// spheres for 30 mm over 20 diameters of a 15 mm slab, where the seed's whole plane holds
// about 180 000.
//
// In the ramp's frame (x down the slope, z normal to it, the teeth's crests at z = R): rained in
// under gravity normal to the ramp (rain_fill.hpp; the region spans the whole periodic box),
// settled, trimmed so the tops reach the thickness above the crests. A static layer tilted to
// the angle would measure h_start, not h_stop: between the two a layer at rest stays at rest
// (Pouliquen's hysteresis). So launch() first sets the layer flowing on a steep ramp (60 deg,
// beyond any theta2) until its mean speed down the slope reaches a Froude number of 0.5,
// sqrt(g h) / 2 (steady flows near h_stop run at about beta h / h_stop = 0.14 of it), then
// turns gravity to the angle, g (sin a, 0, -cos a): the flow either comes to rest or goes on.
//
//   StoppingLayerScene layer(settings, spec);   // settings.gravity is replaced
//   layer.fill(log);
//   layer.launch(log);
//   const LayerOutcome o = run_layer(layer, 4.0, log);  // at rest, run away, or moving at 4 s
#include <memory>
#include <ostream>

#include "fullsim/dem/dem_engine.hpp"
#include "fullsim/dem/scene/rain_fill.hpp"
#include "models/core/time_series.hpp"

namespace feedflow {

struct StoppingLayerSpec {
  double angle = 0.0;            // [rad] of the ramp once tilted
  double thickness = 0.0;        // [m] normal to the ramp above the teeth's crests (the trim)
  double length = 0.0;           // [m] periodic, down the slope, in whole teeth; 0: 20 diameters
  double slab_depth = 0.015;     // [m] periodic, across the ramp (the seed's slab)
  unsigned seed = 1;             // of the rain's random positions
  double settle_speed = 1e-3;    // [m/s] settled when the largest speed is below (seed)
  double max_settle_time = 3.0;  // [s] of settling at most
  double launch_angle = 1.0471975511965976;  // [rad] (60 deg) of the ramp while launching
  double launch_froude = 0.5;  // launched once the mean speed reaches this x sqrt(g h)
};

// How a tilted layer ended.
struct LayerOutcome {
  bool at_rest = false;     // came to rest (else still moving when the run ended)
  bool ran_away = false;    // sped past runs_away()'s mark: flows on (the run ended there)
  double time = 0.0;        // [s] after the tilt: to rest, or the whole run
  double speed = 0.0;       // [m/s] mean down-slope speed at the end
  double peak_speed = 0.0;  // [m/s] largest mean down-slope speed sampled
  double thickness = 0.0;   // [m] measured at the end (StoppingLayerScene::thickness)
};

class StoppingLayerScene {
 public:
  StoppingLayerScene(DemSettings settings, StoppingLayerSpec spec);

  // The rain-fall settings (region over the whole box, following the fill; trim at the
  // thickness).
  RainFillSettings rain() const;
  // Rain-fall, settling and trimming under gravity normal to the ramp (logs each phase).
  const FillReport& fill(std::ostream& log, ProgressSink* progress = nullptr);
  const FillReport& fill_report() const { return fill_report_; }
  // The layer set flowing on the launch angle's ramp (until its mean speed reaches the launch
  // Froude number, or 1 s), then gravity turned to the ramp's angle: the clock of run_layer()
  // starts. Throws std::runtime_error when the launch ramp did not set it flowing.
  void launch(std::ostream& log);
  // Gravity turned to the ramp's angle, g (sin a, 0, -cos a): launch() ends with it, and a
  // restart sets it before the engine is restored from a checkpoint written after the tilt.
  void tilt();
  // A restarted run's tilt time and launch speed, as launch() left them.
  void resume(double tilt_time, double launch_speed);
  double tilt_time() const { return tilt_time_; }
  double launch_speed() const { return launch_speed_; }  // [m/s] when gravity was turned

  // The flow has clearly stopped (bed_at_rest: mean kinetic energy per particle below 1e-3 m g d).
  bool at_rest() const;
  // The flow clearly goes on: its mean speed down the slope has reached kRunAwaySpeedRatio times
  // the launch speed, on a ramp less steep than the launch's. Measured on 16 of the seed's
  // layers at 37-42 deg (3-36 mm, run 2 s after the tilt): the 7 that came to rest never passed
  // 1.09 times their launch speed; 8 of the 9 that flowed on passed 1.5 times it 0.16-1.44 s
  // after the tilt, the ninth ran steadily (at most 1.16 times it).
  static constexpr double kRunAwaySpeedRatio = 1.5;
  bool runs_away() const;
  // Mass-weighted mean velocity down the slope [m/s].
  double downslope_speed() const;
  // The layer's thickness as the seed's DEM measured a deposit: the highest particle top above
  // the crests in each bin one diameter wide, averaged over the periodic length [m].
  double thickness() const;

  double length() const { return length_; }  // the periodic length used [m]
  DemEngine& engine() { return *engine_; }
  const DemEngine& engine() const { return *engine_; }
  const StoppingLayerSpec& spec() const { return spec_; }

 private:
  DemSettings settings_;
  StoppingLayerSpec spec_;
  double length_ = 0.0;
  std::unique_ptr<DemEngine> engine_;
  double tilt_time_ = 0.0;
  double launch_speed_ = 0.0;
  FillReport fill_report_;
};

// How much a tilted layer still slows `t` [s] after the tilt: the mean speed down the slope over
// the last kLayerSlowingWindow over that over the same span kLayerSlowingLag earlier, from the
// rows of `series` (time after the tilt and speed in the columns given); 1 without an earlier
// speed. Below kLayerSlowingRatio the layer is still slowing, at or above it it flows steadily.
// Measured at 35 deg: a 54.4 mm layer of the seed's held its launch speed for 2 s, then fell
// to 0.36 of it by 4 s (ratio 0.6) and came to rest at 5.1 s; a 65.2 mm layer ran at 0.96-1.0
// of it (ratio 0.97). At 34 deg an 82.4 mm layer fell from 1.13 to 0.66 of it over 4 s and
// passed 0.85 while still falling, so a steady verdict asks for 0.95 (speeds of a steady layer
// swing by 10-20 % over a second; it passes 0.95 soon after, a slowing one runs on).
constexpr double kLayerSlowingWindow = 0.5;  // [s]
constexpr double kLayerSlowingLag = 1.0;     // [s]
constexpr double kLayerSlowingRatio = 0.95;
double layer_slowing_ratio(const TimeSeries& series, std::size_t time_column,
                           std::size_t speed_column, double t);

// Runs a tilted layer, sampling every `sample` of simulated time, until it is at rest (after
// 0.1 s at least, so the tilt's first jolt does not count), it runs away (runs_away()) or
// `max_time` has passed since the tilt; one log line per tenth of the run.
LayerOutcome run_layer(StoppingLayerScene& layer, double max_time, std::ostream& log,
                       double sample = 0.02);

}  // namespace feedflow
