#include "designer/verify/dem_run_estimate.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>

#include "designer/simulate/dem_case_settings.hpp"
#include "designer/simulate/dem_drum_adapter.hpp"
#include "designer/simulate/dem_hopper_scene.hpp"
#include "designer/simulate/dem_layer_adapter.hpp"
#include "fullsim/common/progress_line.hpp"
#include "models/units/quantity_format.hpp"

namespace feedflow {

std::string DemRunEstimate::text() const {
  return "about " + format_duration(seconds) +
         (longest_seconds > 1.01 * seconds ? " (at most " + format_duration(longest_seconds) + ")"
                                           : std::string()) +
         " on " + std::to_string(cores) + (cores == 1 ? " core: " : " cores: ") +
         format_number(spheres, 3) + " spheres, " +
         format_number((fill_time + discharge_time) / time_step / 1e6, 2) + " million steps of " +
         format_quantity(time_step, "us", 3);
}

namespace {

// The stable step of `engine`'s law for spheres of `radius`: one sphere in `rain`'s region
// prepares it.
double stable_step(DemEngine& engine, const RainFillSettings& rain, double radius, double density) {
  engine.insert_particle(0.5 * (rain.region_lower + rain.region_upper), radius, density, 0.0,
                         Vec3::Zero());
  std::ostringstream plan;
  engine.prepare(plan);
  return engine.time_step();
}

// The threads a run of `spheres` takes: one below the engine's parallel_from.
int threads_for(double spheres) {
  return spheres < static_cast<double>(DemSettings{}.parallel_from) ? 1 : kDemHopperCores;
}

double sphere_mass(double radius, double density) {
  return density * 4.0 / 3.0 * std::numbers::pi * radius * radius * radius;
}

// A scene whose spheres all move all the while: `rain` inserted and settled at its cap, then
// `launch` [s] and `run` [s] of simulated time (`cap` [s] at the longest), in `engine`'s stable
// step.
DemRunEstimate whole_bed_estimate(DemEngine& engine, const RainFillSettings& rain, double launch,
                                  double run, double cap) {
  DemRunEstimate e;
  e.time_step = stable_step(engine, rain, rain.radius, rain.density);
  e.spheres = std::floor(rain.target_mass / sphere_mass(rain.radius, rain.density));
  e.cores = threads_for(e.spheres);
  const double inserting = rain.target_mass / rain.mass_rate;
  e.fill_time = inserting + rain.settle_time_cap + launch;
  e.discharge_time = run;
  e.run_cap = cap;
  const double before = 0.5 * inserting + rain.settle_time_cap + launch;
  e.particle_steps = e.spheres * (before + run) / e.time_step;
  e.seconds = e.particle_steps / kDemHopperParticleStepsPerSecond;
  e.longest_seconds = e.spheres * (before + cap) / e.time_step / kDemHopperParticleStepsPerSecond;
  return e;
}

}  // namespace

DemRunEstimate estimate_dem_drum_run(const Case& c) {
  const DemSettings settings = dem_drum_settings(c);
  DrumScene scene(settings, dem_drum_spec(c, settings));
  const double rotation = dem_drum_rotation(c);
  return whole_bed_estimate(scene.engine(), scene.rain(), 0.0, rotation, rotation);
}

DemRunEstimate estimate_dem_layer_run(const Case& c) {
  constexpr double kLaunch = 0.3;  // [s] on the 60 deg ramp to a Froude number of 0.5 (measured)
  // [s] after the tilt, as layers end (measured at 37-42 deg: at rest after 0.24-1.84 s, run
  // away after 0.16-1.44 s)
  constexpr double kTypicalRun = 1.5;
  const DemSettings settings = dem_case_settings(c);
  StoppingLayerScene scene(settings, stopping_layer_spec(c, settings));
  const double limit = c.dem.end_time.value_or(kStoppingLayerRunLimit);
  return whole_bed_estimate(scene.engine(), scene.rain(), kLaunch, std::min(kTypicalRun, limit),
                            limit);
}

DemRunEstimate estimate_dem_hopper_run(const Case& c, double reduced_rate) {
  const DemHopperScene scene = hopper_scene_from_case(c);
  const RainFillSettings rain = scene.rain();
  DemEngine probe = hopper_scene_structure(scene);
  DemRunEstimate e;
  e.time_step = stable_step(probe, rain, scene.radius(), scene.density);
  e.spheres = std::floor(rain.target_mass / sphere_mass(scene.radius(), scene.density));
  e.cores = threads_for(e.spheres);
  const double inserting = rain.target_mass / rain.mass_rate;
  e.fill_time = inserting + rain.settle_time_cap;
  const double real_content = rain.target_mass * scene.scale();
  e.discharge_time = reduced_rate > 0.0
                         ? std::min(real_content / reduced_rate, scene.default_duration)
                         : scene.default_duration;
  // Inserting and emptying hold half the spheres on average; settling holds them all.
  e.particle_steps =
      e.spheres * (0.5 * inserting + rain.settle_time_cap + 0.5 * e.discharge_time) / e.time_step;
  e.seconds = e.particle_steps / kDemHopperParticleStepsPerSecond;
  e.run_cap = scene.default_duration;
  e.longest_seconds = e.spheres * (0.5 * inserting + rain.settle_time_cap + e.run_cap) /
                      e.time_step / kDemHopperParticleStepsPerSecond;
  return e;
}

}  // namespace feedflow
