// Time-step stress: DEM and CEL run at 0.5x to 10x their stable step (the DEM's step forced
// above the stable one, the CEL's Courant number above the case file's cap of 1). Every run
// either finishes with finite results or stops with a NumericalFailure (the command line's exit
// 4) that names the step, the particle or cell, and a safe time step. The fast tests run a
// 64-sphere bed and the small CEL hopper; the LONG_ ones the seed's contact law and 10 mm cells.
#include <gtest/gtest.h>

#include <cmath>
#include <regex>
#include <sstream>
#include <string>

#include "fullsim/cel/cel_scene_run.hpp"
#include "fullsim/cel/hopper_scene.hpp"
#include "fullsim/dem/dem_engine.hpp"
#include "models/core/errors.hpp"
#include "models/hypoplastic/hypoplastic_model.hpp"
#include "models/units/angle.hpp"
#include "tests/fullsim/cel/small_hopper.hpp"
#include "tests/fullsim/dem/dem_test_scene.hpp"

namespace feedflow {
namespace {

using namespace dem_test;

constexpr double kFactors[] = {0.5, 1.0, 2.0, 5.0, 10.0};

// How one run ended: finished (with finite state) or the failure's message.
struct StressOutcome {
  bool finished = false;
  bool finite = false;
  std::string failure;
};

// A NumericalFailure names the step, the particle or cell, and a time step that is safe.
void expect_named_failure(const std::string& message, const char* rung) {
  EXPECT_TRUE(std::regex_search(message, std::regex("at step [0-9]+"))) << rung << ": " << message;
  EXPECT_TRUE(std::regex_search(message, std::regex(rung == std::string("DEM") ? "particle id [0-9]+" : "cell \\([0-9]+, [0-9]+\\)")))
      << message;
  EXPECT_TRUE(std::regex_search(message, std::regex("(safe time step is|time step below) [0-9.e+-]+ s")))
      << message;
}

// 64 Hertz spheres dropped into a closed box, run for `duration` at `factor` x the stable step.
StressOutcome dem_bed(double factor, double duration, ContactLawChoice law) {
  ParticleStore p;
  add_lattice(p, Vec3(2e-3, 2e-3, 1.6e-3), 4, 4, 4, 2.95e-3, 0.5);
  const Vec3 lower(0, 0, 0), upper(0.016, 0.016, 0.02);
  DemSettings s = hertz_settings(0.5, 0.5, 0.1);
  s.law = law;
  s.stable_step_fraction = factor;
  s.force_time_step = factor > 1.0;
  DemEngine e(s, SimulationBox{lower, upper, {false, false, false}}, p);
  e.add_wall(Wall::plane("floor", lower, Vec3::UnitZ()));
  add_side_walls(e, lower, upper);
  e.add_wall(Wall::plane("top", upper, -Vec3::UnitZ()));
  StressOutcome out;
  try {
    std::ostringstream log;
    e.prepare(log);
    e.advance_to(duration);
    out.finished = true;
    out.finite = std::isfinite(e.kinetic_energy());
    for (std::size_t i = 0; i < e.particles().size(); ++i)
      out.finite = out.finite && e.particles().position[i].allFinite();
  } catch (const NumericalFailure& f) {
    out.failure = f.what();
  }
  return out;
}

// The small CEL hopper (20 mm cells) for `duration` at `factor` x the default Courant number.
StressOutcome cel_hopper(double factor, double duration, double cell) {
  cel::CelScene scene = cel::make_hopper_scene(testing::small_wedge(), 8.5 * kDegree, {290.0, 0.7102}, cell);
  scene.options.time_step.safety *= factor;
  scene.options.time_step.max_time_step *= factor;  // the cap too, or it hides the factor
  StressOutcome out;
  try {
    cel::CelSceneRun run(scene, make_hypoplastic_model(loblolly_pine_table1()));
    std::ostringstream log;
    run.prepare(log);
    while (!run.reached(duration)) run.advance_to(duration);  // on past the gravity phase's end
    out.finished = true;
    out.finite = std::isfinite(run.solver().kinetic_energy()) && std::isfinite(run.solver().total_mass());
  } catch (const NumericalFailure& f) {
    out.failure = f.what();
  }
  return out;
}

void expect_finite_or_named(const StressOutcome& o, double factor, const char* rung) {
  if (o.finished) {
    EXPECT_TRUE(o.finite) << rung << " at " << factor << "x finished with a non-finite state";
  } else {
    expect_named_failure(o.failure, rung);
  }
}

// DEM, Hertz: at and below the stable step the bed settles; above it every run ends finite or
// stops naming the step, the particle and a safe step. At 10x the guard must stop it.
TEST(TimeStepStress, DemFiniteOrStoppedNamingASafeStep) {
  const ContactLawChoice hertz = choose_contact_law("hertz", "mindlin", "cdt", "none");
  for (double f : kFactors) {
    const StressOutcome o = dem_bed(f, 0.05, hertz);
    if (f <= 1.0) {
      EXPECT_TRUE(o.finished && o.finite) << f << "x: " << o.failure;
    }
    expect_finite_or_named(o, f, "DEM");
  }
  EXPECT_FALSE(dem_bed(10.0, 0.05, hertz).finished);  // a 10x step is not silently accepted
}

// CEL: at the default Courant number and half of it the hopper fills and settles; up to 10x
// every run ends finite or stops naming the step, the cell and a safe step. At 10x the guard
// must stop it.
TEST(TimeStepStress, CelFiniteOrStoppedNamingASafeStep) {
  for (double f : kFactors) {
    const StressOutcome o = cel_hopper(f, 0.15, 0.02);
    if (f <= 1.0) {
      EXPECT_TRUE(o.finished && o.finite) << f << "x: " << o.failure;
    }
    expect_finite_or_named(o, f, "CEL");
  }
  EXPECT_FALSE(cel_hopper(10.0, 0.15, 0.02).finished);  // a Courant number of 8 is not silently accepted
}

// The seed's hysteretic law (a ~20x smaller step) over the same factors, for longer.
TEST(TimeStepStress, LONG_DemSeedLawFiniteOrStopped) {
  const ContactLawChoice seed = choose_contact_law("hysteretic_nonlinear2", "history", "cdt", "none");
  for (double f : kFactors) expect_finite_or_named(dem_bed(f, 0.1, seed), f, "DEM");
}

// 10 mm cells through the gravity phase and the first discharge.
TEST(TimeStepStress, LONG_CelFineGridFiniteOrStopped) {
  for (double f : kFactors) expect_finite_or_named(cel_hopper(f, 0.6, 0.01), f, "CEL");
}

}  // namespace
}  // namespace feedflow
