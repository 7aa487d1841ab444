#pragma once
// What a DEM run of a hopper or a drum case will cost, before it is made: the plan of `--verify`
// on the particle rung, and the wall time a MARGINAL verdict quotes beside the command that would
// settle it. The scene says the spheres (the fill's target mass over one sphere's: an upper
// bound, the fill stops at its height), the time step (the stable one of the case's contact
// law) and the simulated times (inserting, settling at its cap, then a hopper's discharge at the
// reduced rate until it is empty, capped by the scene's end, or a drum's whole rotation); the
// wall time is their particle-steps at the rate the DEM hopper ran at on two cores of the bench
// machine. A hopper run that arches stops sooner; one whose grains flow slower than the reduced
// rate takes longer (the pilot's emptied 18-23 % later than estimated, RECORD.md).
#include <string>

#include "designer/case/case.hpp"

namespace feedflow {

// [particle-steps/s] (drums are planned at the same rate) the pilot hopper's DEM run at 45 mm
// (hysteretic_nonlinear2 + k_nc, 7768 spheres, 0.35 m fill) kept from its fill to its emptying, on
// the two threads of the bench machine, 2026-12-06: 3534 s at 6.38e6 and 1185 s at 7.71e6 (its
// performance blocks).
// A scene below DemSettings::parallel_from spheres runs on one thread whatever OMP_NUM_THREADS
// says, at about that rate too (stopping layers of 1 300-1 900 spheres on one thread,
// 2026-12-07: 6.3-7.3e6 at 14-42 mm).
constexpr double kDemHopperParticleStepsPerSecond = 6.7e6;
constexpr int kDemHopperCores = 2;

struct DemRunEstimate {
  double spheres = 0.0;         // filled (upper bound)
  double time_step = 0.0;       // [s]
  double fill_time = 0.0;       // [s] simulated: inserting and settling
  double discharge_time = 0.0;  // [s] simulated after the opening
  double particle_steps = 0.0;  // the fill's, then the discharge's (the hopper emptying evenly)
  double seconds = 0.0;         // [s] wall, at kDemHopperParticleStepsPerSecond
  // [s] wall should it flow, too slowly to empty, until the scene's end `run_cap` [s] after the
  // opening with all its spheres (near B_c the flow slows to a trickle, as the pilot hopper's
  // k_nc run at 31.3 mm did).
  double longest_seconds = 0.0;
  double run_cap = 0.0;
  int cores = kDemHopperCores;  // the run's threads: one below DemSettings::parallel_from spheres

  // "about 1 h 05 min (at most 6 h 10 min) on 2 cores: 9723 spheres, 4.8 million steps of
  // 0.745 us"
  std::string text() const;
};

// The estimate for one DEM run of the drum case `c`, to the end of its rotation (dem.end_time or
// the seed's 10 s; a run whose angle settles sooner stops sooner): all its spheres turn all the
// while, so `seconds` and `longest_seconds` are one. Throws InputError as the scene does.
DemRunEstimate estimate_dem_drum_run(const Case& c);

// The estimate for one DEM stopping layer of the chute case `c` ([dem] stopping_layer set): its
// fill, launch and the run after the tilt (1.5 s as layers end at rest or run away, at most
// dem.end_time or the 10 s limit), all its spheres all the while. Throws InputError as the
// scene does.
DemRunEstimate estimate_dem_layer_run(const Case& c);

// The estimate for one DEM run of the hopper case `c` (its [dem] settings as the run will have
// them), whose reduced discharge rate is `reduced_rate` [kg/s of the real hopper]. Throws
// InputError, as the scene does, for a case the DEM scene cannot build.
DemRunEstimate estimate_dem_hopper_run(const Case& c, double reduced_rate);

}  // namespace feedflow
