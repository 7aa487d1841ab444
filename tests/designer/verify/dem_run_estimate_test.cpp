// The cost of a DEM hopper run before it is made (designer/verify/dem_run_estimate), against the
// pilot hopper's run it must plan: 45 mm outlet, 0.35 m fill, the seed's hysteretic law with K_nc
// cohesion, run from its fill to its emptying on two threads on 2026-12-06 (its log: 7768
// spheres inserted, dt 7.452e-7 s, gate removed at 1.08 s, emptied at 5.93 s, 3534 s + 1185 s).
#include <gtest/gtest.h>

#include "designer/case/case_loader.hpp"
#include "designer/design/design_check.hpp"
#include "designer/verify/dem_run_estimate.hpp"
#include "fullsim/dem/dem_engine.hpp"

namespace feedflow {
namespace {

Case pilot_at_45mm() {
  return load_case("cases/pilot_hopper.toml",
                   std::vector<SetOverride>{{"hopper.outlet_width", "45mm"},
                                            {"hopper.fill_height", "0.35m"},
                                            {"dem.cohesion", "k_nc"}});
}

double reduced_rate(const Case& c) {
  const DesignRecord r = design_check(c, ModelChoices{});
  return std::get<double>(find_estimate(r.results, "mass_flow_rate")->value);
}

// The step is the run's own (the stable step of its law), the spheres bound the fill from above,
// and the wall time lands within 40 % of the 4719 s the run took.
TEST(DemRunEstimate, PlansThePilotHoppersMeasuredRun) {
  const Case c = pilot_at_45mm();
  const DemRunEstimate e = estimate_dem_hopper_run(c, reduced_rate(c));
  EXPECT_NEAR(e.time_step, 7.452e-7, 0.001 * 7.452e-7);
  EXPECT_GE(e.spheres, 7768.0);
  EXPECT_LE(e.spheres, 1.3 * 7768.0);
  EXPECT_NEAR(e.fill_time, 1.08, 0.15);
  EXPECT_GT(e.seconds, 4719.0 / 1.4);
  EXPECT_LT(e.seconds, 4719.0 * 1.4);
  EXPECT_NE(e.text().find("on 2 cores: 9723 spheres"), std::string::npos) << e.text();
}

// Half the rate empties the hopper in twice the time; no rate at all runs to the scene's end,
// and the longest keeps every sphere that long.
TEST(DemRunEstimate, DischargeTakesTheContentOverTheRateUpToTheScenesEnd) {
  const Case c = pilot_at_45mm();
  const double q = reduced_rate(c);
  const DemRunEstimate full = estimate_dem_hopper_run(c, q),
                       half = estimate_dem_hopper_run(c, 0.5 * q);
  EXPECT_NEAR(half.discharge_time, 2.0 * full.discharge_time, 1e-12);
  EXPECT_GT(half.seconds, full.seconds);
  EXPECT_DOUBLE_EQ(estimate_dem_hopper_run(c, 0.0).discharge_time, 20.0);
  // The longest: every sphere kept until the scene's end, above any discharge that empties.
  EXPECT_DOUBLE_EQ(full.run_cap, 20.0);
  EXPECT_GT(full.longest_seconds, estimate_dem_hopper_run(c, 0.0).seconds);
}

// A drum turns all its spheres for its whole rotation (the seed's 10 s, or dem.end_time): on the
// seed's drum as an 18 mm slab with the seed's law, ten more seconds cost spheres x 10 s / dt
// more particle-steps, and the run's estimate is also its most.
TEST(DemRunEstimate, ADrumTurnsAllItsSpheresForItsRotation) {
  const auto drum = [](const char* end) {
    return load_case("cases/rotating_drum_20rpm.toml",
                     std::vector<SetOverride>{{"dem.slab_depth", "18mm"}, {"dem.end_time", end}});
  };
  const DemRunEstimate ten = estimate_dem_drum_run(drum("10s")),
                       twenty = estimate_dem_drum_run(drum("20s"));
  EXPECT_NEAR(ten.time_step, 7.452e-7, 0.001 * 7.452e-7);  // the seed's law, as in the hopper
  EXPECT_DOUBLE_EQ(ten.run_cap, 10.0);
  EXPECT_DOUBLE_EQ(ten.seconds, ten.longest_seconds);
  EXPECT_NEAR(twenty.particle_steps - ten.particle_steps, ten.spheres * 10.0 / ten.time_step,
              1e-9 * twenty.particle_steps);
}

// A stopping layer of the seed's spheres holds fewer than the engine's parallel_from (4 000): it
// runs on one thread whatever OMP_NUM_THREADS says, and its estimate says one core; the pilot
// hopper's 9 723 run on two.
TEST(DemRunEstimate, ALayerBelowTheEnginesParallelSizeRunsOnOneCore) {
  const Case layer =
      load_case("cases/inclined_plane_29_5.toml",
                std::vector<SetOverride>{{"chute.angle", "37deg"}, {"dem.stopping_layer", "42mm"}});
  const DemRunEstimate e = estimate_dem_layer_run(layer);
  EXPECT_LT(e.spheres, static_cast<double>(DemSettings{}.parallel_from));
  EXPECT_EQ(e.cores, 1);
  EXPECT_NE(e.text().find(" on 1 core: "), std::string::npos) << e.text();
  const Case c = pilot_at_45mm();
  EXPECT_EQ(estimate_dem_hopper_run(c, reduced_rate(c)).cores, 2);
}

}  // namespace
}  // namespace feedflow
