// The CEL drum's bed state (fullsim/cel/drum_bed_state.hpp), what its regime is classified
// from, on the seed drum at 10 mm cells: a bed the shell carries and a bed a frictionless shell
// slides under give the two limits of the measures, and the classifier names them.
#include <gtest/gtest.h>

#include "fullsim/cel/cel_scene_run.hpp"
#include "fullsim/cel/drum_bed_state.hpp"
#include "fullsim/cel/drum_scene.hpp"
#include "models/units/angle.hpp"
#include "tests/fullsim/cel/seed_drum.hpp"

namespace feedflow::cel {
namespace {

// The seed drum (145 mm, 50 % fill, 20 rpm), loose pine, 10 mm cells, `turning` seconds after
// the shell starts; the bed state then.
DrumBedState turned_bed(double wall_friction_angle, DrumFrame frame, double turning) {
  const Drum drum = seed_drum(20.0);
  const double h = 0.01;
  CelScene scene = make_drum_scene(drum, wall_friction_angle, {290.0, 0.7102}, h, frame);
  CelSceneRun run(scene, make_hypoplastic_model(loblolly_pine_table1()));
  while (run.phase() == ScenePhase::gravity) run.step();
  while (run.solver().time() < run.event_time() + turning) run.step();
  const DrumSection d = drum_section(drum, h);
  return drum_bed_state(run.solver(), d, drum_surface(run.solver(), d, 1.0), drum.speed);
}

// A 20 deg shell carries the settled bed before its first avalanche (0.3 s, 36 deg of turn):
// the bed turns with the shell as a solid body, the layer at the shell at the shell's speed,
// nothing in flight or over the top, and the surface stays a straight line.
TEST(CelDrumBedState, RoughShellCarriesTheBedAsASolidBody) {
  const DrumBedState b = turned_bed(20.0 * kDegree, DrumFrame::shell, 0.3);
  EXPECT_GT(b.solid_body_fraction, 0.9);
  EXPECT_GT(b.shell_speed_ratio, 0.8);  // the shell cells' centres lie inside R: at most 1
  EXPECT_LT(b.shell_speed_ratio, 1.0);
  EXPECT_EQ(b.airborne_fraction, 0.0);
  EXPECT_EQ(b.over_top_fraction, 0.0);
  EXPECT_LT(b.surface_bulge, 0.1);
}

// A frictionless shell passes on no torque (solved in the laboratory frame, the shell turning
// on the grid): the bed stays at rest, its shell layer moves at a small share of the shell's
// speed and almost none of it turns with the shell, so the classifier calls it slipping.
TEST(CelDrumBedState, FrictionlessShellSlipsUnderTheBed) {
  const DrumBedState b = turned_bed(0.0, DrumFrame::laboratory, 0.3);
  EXPECT_LT(b.shell_speed_ratio, 0.2);
  EXPECT_LT(b.solid_body_fraction,
            0.1);  // only the cells near the axis, where omega r < 0.1 omega R
  EXPECT_EQ(classify_drum_bed(b).regime, DrumBedRegime::slipping);
}

}  // namespace
}  // namespace feedflow::cel
