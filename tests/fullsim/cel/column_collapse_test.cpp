// Plane-strain granular column collapse against the published experimental runout scaling
// (issue 7). Published (quasi-)2D laws, normalised runout (L_inf - L0)/L0 against a = H0/L0:
//  - Lube, Huppert, Sparks & Freundt 2005, Phys. Rev. E 72, 041301 (2D channel): linear,
//    ~1.2-1.6 a, below a ~ 2-3 and ~a^(2/3) above (the summary); the coefficients used
//    here, 1.2 a for a < 1.8 and 1.9 a^(2/3) for a > 2.8, are recalled from the paper, not read
//    from it (its text was not found with the search tool);
//  - Lajeunesse, Monnier & Homsy 2005, Phys. Fluids 17, 103302 (quasi-2D): ~1.2 a at small a,
//    ~a^(2/3) above (the summary, same caveat);
//  - Staron & Hinch 2005, J. Fluid Mech. 545, 1-27 (2D contact-dynamics grains; abstract found:
//    "the normalized runout distance has a power-law dependence on the aspect ratio a").
// Our law is the Table 1 loblolly-pine set of the hypoplastic model (the material; no
// cohesionless sand set exists in models/hypoplastic). That set mobilises 56-73 deg in simple
// shear at these pressures (fullsim/README.md), far above the 30-35 deg of the glass beads and
// sands of the experiments, so the runout is expected shorter than the scaling; the tests
// compare it with min(1.2 a, 1.9 a^(2/3)) within stated tolerances (fast: 0.4 ... 1.5 times it,
// LONG_: 0.5 ... 2 times it), measured 0.5-0.8 times it (fullsim/README.md).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "fullsim/cel/cel_scene_run.hpp"
#include "fullsim/cel/column_collapse_scene.hpp"
#include "tests/fullsim/cel/pine_scene_material.hpp"

namespace feedflow::cel {
namespace {

using testing::kPine;
using testing::pine;

// Lube et al.: 1.2 a below, 1.9 a^(2/3) above; the two meet at a = 3.97, take the smaller.
double published_runout(double a) { return std::min(1.2 * a, 1.9 * std::pow(a, 2.0 / 3.0)); }

struct Collapse {
  double normalised_runout = 0.0;  // (L - L0) / L0 when the collapse came to rest [-]
  double creep = 0.0;              // growth of that runout over the following `creep_time`
  double rest_time = 0.0, mass_error = 0.0;
  bool at_rest = false;
};

// Runs a column until the collapse is at rest: after the gate is removed (at least 0.1 s), the
// kinetic energy below 1e-3 of its peak since the event (at most `max_time`). The Table 1 law
// does not stay there: the deposit creeps on (measured on the a = 1 column at 10 mm cells: KE
// down to 5e-4 of the peak at 0.5 s, back up to 3.6e-3 at 2 s while the runout grows from 0.62
// to 0.65), so the run goes on for `creep_time` and reports the runout's growth.
Collapse collapse(double a, double l0, double h, double max_time, double creep_time,
                  const RemapOptions& remap = {}) {
  CelScene scene = make_column_collapse_scene({a, l0, 1.0 + 1.9 * std::pow(a, 2.0 / 3.0) + 1.2 * a},
                                              kPine, h);
  scene.options.remap = remap;
  scene.gravity.ramp_time = 0.3;
  scene.gravity.min_time = 0.35;
  CelSceneRun run(scene, pine());
  while (run.phase() == ScenePhase::gravity) run.step();
  const double t0 = run.event_time(), m0 = run.solver().total_mass();
  double peak = 0.0;
  Collapse c;
  while (run.solver().time() < t0 + max_time) {
    run.step();
    const double ke = run.solver().kinetic_energy();
    peak = std::max(peak, ke);
    if (run.solver().time() > t0 + 0.1 && ke < 1e-3 * peak) {
      c.at_rest = true;
      break;
    }
  }
  const CelSolver& s = run.solver();
  c.normalised_runout = (runout(s) - l0) / l0;
  c.rest_time = s.time() - t0;
  run.solver().run_until(s.time() + creep_time);
  c.creep = (runout(s) - l0) / l0 - c.normalised_runout;
  c.mass_error = (s.total_mass() + s.removed_mass()) / m0 - 1.0;
  std::printf("a = %.2g, L0 = %.3g m, h = %.3g m: (L - L0)/L0 = %.3f at rest after %.3f s "
              "(published scaling %.3f, ratio %.2f), then +%.3f in %.2g s; mass error %.2e\n",
              a, l0, h, c.normalised_runout, c.rest_time, published_runout(a),
              c.normalised_runout / published_runout(a), c.creep, creep_time, c.mass_error);
  return c;
}

// Small columns (L0 = 0.1 m, 10 mm cells) at a = 1 and 2 come to rest, conserve mass, spread
// further at the larger a, and lie within the stated tolerance of the published scaling:
// 0.4 ... 1.5 times it (measured 0.62 and 1.57, i.e. 0.52 and 0.65 of 1.2 a: shorter, as
// expected of the strong Table 1 law), creeping on by less than 0.1 L0 in the next 0.2 s.
TEST(CelColumnCollapse, SmallColumnsComeToRestAndSpreadWithAspectRatio) {
  const Collapse one = collapse(1.0, 0.1, 0.01, 1.5, 0.2);
  const Collapse two = collapse(2.0, 0.1, 0.01, 1.5, 0.2);
  for (const auto& [a, c] : {std::pair{1.0, one}, {2.0, two}}) {
    EXPECT_TRUE(c.at_rest);
    EXPECT_LT(std::abs(c.mass_error), 1e-12);
    EXPECT_GT(c.normalised_runout, 0.4 * published_runout(a));
    EXPECT_LT(c.normalised_runout, 1.5 * published_runout(a));
    EXPECT_LT(c.creep, 0.1);
  }
  EXPECT_GT(two.normalised_runout, one.normalised_runout + 0.2);
  RecordProperty("runout_a1", std::to_string(one.normalised_runout));
  RecordProperty("runout_a2", std::to_string(two.normalised_runout));
}

// Larger columns (L0 = 0.1 m, 5 mm cells; a = 0.5 ... 4), first order (0) and second order +
// PLIC (1): the runout at rest against the published scaling within a factor 2 (the stated
// tolerance; a failure says the law is too strong or too weak, see the header).
class CelColumnCollapseLong : public ::testing::TestWithParam<int> {};

TEST_P(CelColumnCollapseLong, LONG_RunoutAgainstPublishedScaling) {
  RemapOptions remap;
  if (GetParam() == 1) {
    remap = second_order_state();
    remap.material_flux = MaterialFlux::plic;
  }
  for (double a : {0.5, 1.0, 2.0, 4.0}) {
    const Collapse c = collapse(a, 0.1, 0.005, 4.0, 0.5, remap);
    EXPECT_TRUE(c.at_rest);
    EXPECT_LT(std::abs(c.mass_error), 1e-12);
    EXPECT_GT(c.normalised_runout, 0.5 * published_runout(a));
    EXPECT_LT(c.normalised_runout, 2.0 * published_runout(a));
  }
}

INSTANTIATE_TEST_SUITE_P(Remaps, CelColumnCollapseLong, ::testing::Values(0, 1));

}  // namespace
}  // namespace feedflow::cel
