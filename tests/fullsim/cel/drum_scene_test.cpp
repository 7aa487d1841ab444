// The CEL drum scene (issue 7) on the seed drum at 10 mm cells: Coulomb friction at the nodes of
// the rotating shell (models.md 2.6, option C1) carries the bed only through friction.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <numbers>

#include "fullsim/cel/cel_scene_run.hpp"
#include "fullsim/cel/drum_scene.hpp"
#include "fullsim/cel/scene_measurements.hpp"

namespace feedflow::cel {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

struct DrumTurn {
  double largest_angle = 0.0;  // of the free surface after the start [rad]
  double final_angle = 0.0;    // at the end [rad]
};

// The seed drum (145 mm, 50 % fill, 20 rpm), loose pine, 10 mm cells, run `turning` seconds
// after the shell starts; the surface slope over the central half of the diameter.
DrumTurn turn_drum(double wall_friction_angle, double turning) {
  Drum drum;
  drum.diameter = 0.145;
  drum.length = 0.202;
  drum.fill_fraction = 0.5;
  drum.speed = 20.0 * 2.0 * std::numbers::pi / 60.0;
  const double h = 0.01;
  CelScene scene = make_drum_scene(drum, wall_friction_angle, {290.0, 0.7102}, h);
  CelSceneRun run(scene, make_hypoplastic_model(loblolly_pine_table1()));
  while (run.phase() == ScenePhase::gravity) run.step();
  const DrumSection d = drum_section(drum, h);
  DrumTurn t;
  while (run.solver().time() < run.event_time() + turning) {
    run.step();
    const auto s = free_surface(run.solver(), d.centre.x() - 0.5 * d.radius,
                                d.centre.x() + 0.5 * d.radius);
    t.largest_angle = std::max(t.largest_angle, s.slope_angle);
    t.final_angle = s.slope_angle;
  }
  std::printf("wall friction %.0f deg: largest surface angle %.2f deg, after %.2f s %.2f deg\n",
              wall_friction_angle / kDeg, t.largest_angle / kDeg, turning, t.final_angle / kDeg);
  return t;
}

// A frictionless shell transmits no torque: the bed stays level (measured 0.4 deg at most,
// the remap's noise) while the shell turns by 48 deg.
TEST(CelDrumScene, FrictionlessShellLeavesTheBedLevel) {
  EXPECT_LT(turn_drum(0.0, 0.4).largest_angle, 2.0 * kDeg);
}

// A 20 deg shell (the seed FEM's) carries the bed with it before it fails: after 0.4 s at
// 20 rpm (48 deg of shell rotation) the surface has turned by most of that and by no more
// (measured 44 deg; friction cannot turn the bed faster than the shell).
TEST(CelDrumScene, RoughShellCarriesTheBedAtMostAtShellSpeed) {
  const DrumTurn t = turn_drum(20.0 * kDeg, 0.4);
  EXPECT_GT(t.final_angle, 35.0 * kDeg);
  EXPECT_LT(t.largest_angle, 0.4 * 20.0 * 2.0 * std::numbers::pi / 60.0 + 3.0 * kDeg);
}

}  // namespace
}  // namespace feedflow::cel
