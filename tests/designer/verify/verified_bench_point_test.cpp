// A bench point that asks for a verified design check (designer/verify/verified_bench_point): the
// DEM twin of the pilot hopper at a 10 mm outlet, its interlocking width bisected to 30 mm over
// 3-8 of its 6 mm spheres. Its runs are laid down beforehand as the verification keeps them
// (flowing at 48 mm, arching at 18 and 10 mm, each with its wall time and commit), so the point
// reads them back without a DEM step.
#include <gtest/gtest.h>
#include <unistd.h>

#include "designer/verify/verified_bench_point.hpp"
#include "kept_runs.hpp"

namespace feedflow {
namespace {

namespace fs = std::filesystem;
using testing::lay_down_run;

// The point's answer is the bisection's bracket (arches at 18 mm, flows at 48 mm) on rung L3;
// its wall time is its three runs' (1 + 2 + 4 s) and its commit names both of theirs; made from
// kept runs alone it says no run was made, yet it is saved, and asked again it is read back.
TEST(VerifiedBenchPoint, AnswersWithTheBisectionsBracketAndItsRunsTime) {
  BenchQuestion q;
  q.id = "twin_interlocking";
  q.case_file = "tests/data/dem_hopper_twin.toml";
  q.sets = {"hopper.outlet_width=10mm"};
  BenchPoint p;
  p.setting = "DEM hertz bisection";
  p.rung = "L3";
  p.quantity = "mechanical_arching_width_dem_spheres";
  p.verify = "dem";
  p.width_tolerance = "30mm";
  const fs::path folder =
      fs::temp_directory_path() / ("feedflow_verified_point_" + std::to_string(::getpid()));
  fs::remove_all(folder);
  lay_down_run(q, p, folder / "verify", 0.010, "arched", 1.0, "aaaa");
  lay_down_run(q, p, folder / "verify", 0.048, "flowing", 2.0, "bbbb");
  lay_down_run(q, p, folder / "verify", 0.018, "arched", 4.0, "aaaa");
  bool made = false;
  const BenchRun run = run_or_read_back_verified(q, p, FEEDFLOW_SOURCE_DIR, folder, made);
  ASSERT_TRUE(run.done()) << run.status;
  EXPECT_FALSE(made);  // every DEM run was read back
  EXPECT_TRUE(fs::exists(folder / "run.json"));
  EXPECT_EQ(run.invocation,
            "design tests/data/dem_hopper_twin.toml --set hopper.outlet_width=10mm --verify dem "
            "--width-tolerance 30mm --budget 10000h");
  const auto& w = run.results.at("mechanical_arching_width_dem_spheres");
  EXPECT_EQ(w.at("rung"), "L3");
  EXPECT_DOUBLE_EQ(w.at("low").get<double>(), 0.018);
  EXPECT_DOUBLE_EQ(w.at("high").get<double>(), 0.048);
  EXPECT_EQ(run.results.at("arching").at("value"), "arched");
  EXPECT_DOUBLE_EQ(run.wall_seconds, 7.0);
  EXPECT_EQ(run.commit, "aaaa; bbbb");
  const BenchRun again = run_or_read_back_verified(q, p, FEEDFLOW_SOURCE_DIR, folder, made);
  EXPECT_FALSE(made);
  EXPECT_EQ(again.results, run.results);
  fs::remove_all(folder);
}

}  // namespace
}  // namespace feedflow
