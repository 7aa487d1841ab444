#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "fullsim/dem/blow_up_guard.hpp"
#include "fullsim/dem/time_step_choice.hpp"
#include "models/core/errors.hpp"

namespace feedflow {
namespace {

// Kinetic energy beyond twice (initial + gravity work) + floor stops the run and names the
// fastest particle; within the allowance (gravity having fed the energy) it passes.
TEST(BlowUpGuard, EnergyGrowthWithoutSourceFiresNamingTheFastestParticle) {
  ParticleStore p;
  p.add(Vec3(0, 0, 0), 1e-3, 1000.0, 0, Vec3(0.1, 0, 0));
  p.add(Vec3(0.01, 0, 0), 1e-3, 1000.0, 0, Vec3(0, 0, 3.0));
  const double ke = p.kinetic_energy();
  BlowUpGuard guard({0.3, 2.0}, 2.5e-6);
  guard.start(0.01 * ke, 0.0);
  guard.add_gravity_work(0.6 * ke);  // 2 x (0.01 + 0.6) ke > ke: fed by gravity
  EXPECT_NO_THROW(guard.check_state(p, ke, 10));
  guard.start(0.01 * ke, 0.0);      // no source
  try {
    guard.check_state(p, ke, 42);
    FAIL() << "energy growth not caught";
  } catch (const NumericalFailure& f) {
    const std::string m = f.what();
    EXPECT_NE(m.find("at step 42"), std::string::npos) << m;
    EXPECT_NE(m.find("particle id 1 at (0.01, 0, 0)"), std::string::npos) << m;
    EXPECT_NE(m.find("2.5e-06 s"), std::string::npos) << m;
  }
}

// With moving walls the energy check stays on: the floor the engine sets for a wall surface
// speed (M (v_wall + sqrt(2 g dz))^2 / 2) admits a bed driven at that speed and still stops
// energy growing ten times beyond it.
TEST(BlowUpGuard, MovingWallsRaiseTheFloorButKeepTheCheck) {
  ParticleStore p;
  p.add(Vec3(0, 0, 0), 1e-3, 1000.0, 0, Vec3(0.5, 0, 0));
  const double v_wall = 0.5, floor = 0.5 * p.total_mass() * v_wall * v_wall;
  BlowUpGuard guard({0.3, 2.0}, 2.5e-6);
  guard.start(0.0, floor, v_wall);
  EXPECT_NO_THROW(guard.check_state(p, p.kinetic_energy(), 1));
  p.velocity[0] = Vec3(0.5 * std::sqrt(10.0), 0, 0);
  EXPECT_THROW(guard.check_state(p, p.kinetic_energy(), 2), NumericalFailure);
  EXPECT_NE(guard.describe().find("moving walls up to 0.5 m/s"), std::string::npos) << guard.describe();
}

// The stable step is used by default with its justification; a smaller user step is taken
// with a warning, a larger one refused unless forced.
TEST(TimeStepChoice, StableByDefaultSmallerWarnsLargerRefusedUnlessForced) {
  const StableTimeStep stable{1e-5, "period 2e-4 s / 20"};
  const TimeStepChoice def = choose_time_step(stable, 0.0, false);
  EXPECT_EQ(def.value, 1e-5);
  EXPECT_NE(def.justification.find("period 2e-4 s / 20"), std::string::npos);
  EXPECT_TRUE(def.warning.empty());
  const TimeStepChoice small = choose_time_step(stable, 1e-6, false);
  EXPECT_EQ(small.value, 1e-6);
  EXPECT_NE(small.warning.find("below the stable step"), std::string::npos);
  EXPECT_THROW(choose_time_step(stable, 3e-5, false), InputError);
  const TimeStepChoice forced = choose_time_step(stable, 3e-5, true);
  EXPECT_EQ(forced.value, 3e-5);
  EXPECT_NE(forced.warning.find("FORCED"), std::string::npos);
}

// The stable step as printed (4 significant digits) and typed back is taken as the stable step
// itself, the same bits as the default run; a step beyond the printed rounding is still refused,
// and the refusal gives advice a user can follow.
TEST(TimeStepChoice, PrintedStableStepTypedBackIsTheStableStep) {
  const StableTimeStep stable{7.45161e-7, "the seed law"};
  for (const double typed : {7.452e-7, 7.451e-7, 7.4516e-7}) {  // "%.4g" rounds up, down, or more digits
    const TimeStepChoice c = choose_time_step(stable, typed, false);
    EXPECT_EQ(c.value, stable.value) << typed;
    EXPECT_TRUE(c.warning.empty()) << typed;
  }
  try {
    choose_time_step(stable, 7.46e-7, false);
    ADD_FAILURE() << "a step 0.11 % above the stable one was accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()).find("force"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("7.452e-07 s"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace feedflow
