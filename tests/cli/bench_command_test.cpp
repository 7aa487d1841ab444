// `feedflow bench` as a user runs it: the reduced-model points of one question, the outputs,
// and a second run that reads the runs back instead of making them again.
#include <map>

#include <gtest/gtest.h>

#include <algorithm>

#include <nlohmann/json.hpp>

#include "run_feedflow.hpp"

namespace fs = std::filesystem;
using namespace feedflow::testing;

namespace {

// The four discharge models of the pilot hopper at 60 mm: bench.json and bench.csv hold one
// answer each with its value and wall time (no reference without the CEL runs); run again, all
// four are read back (resumable) and the answers are the same.
TEST(BenchCommand, ReducedModelPointsAreMadeOnceAndReadBack) {
  const fs::path dir = scratch_folder("feedflow_bench", true);
  const std::string args = "bench --quick --rungs L0 --only hopper_discharge_rate_60mm --out b";
  const feedflow::testing::Run first = run_feedflow(args, dir);
  ASSERT_EQ(first.exit_code, 0) << first.err;
  EXPECT_NE(first.out.find("4 run(s) made, 0 read back"), std::string::npos) << first.out;
  const auto json = nlohmann::json::parse(slurp(dir / "b" / "bench.json"));
  ASSERT_EQ(json["questions"].size(), 1u);
  const auto& answers = json["questions"][0]["answers"];
  int answered = 0;
  for (const auto& a : answers)
    if (a["status"] == "done") {
      ++answered;
      EXPECT_GT(a["value"].get<double>(), 1.0);  // kg/s of the pilot hopper: 2-6
      EXPECT_LT(a["value"].get<double>(), 10.0);
      EXPECT_EQ(a["unit"], "kg/s");
      EXPECT_GE(a["wall_seconds"].get<double>(), 0.0);
    } else {
      EXPECT_EQ(a["status"], "not run");  // the CEL and DEM points
    }
  EXPECT_EQ(answered, 4);
  EXPECT_EQ(json["questions"][0]["reference"]["source"], "");
  const feedflow::testing::Run again = run_feedflow(args, dir);
  ASSERT_EQ(again.exit_code, 0) << again.err;
  EXPECT_NE(again.out.find("0 run(s) made, 4 read back"), std::string::npos) << again.out;
  EXPECT_EQ(nlohmann::json::parse(slurp(dir / "b" / "bench.json"))["questions"], json["questions"]);
  const std::string csv = slurp(dir / "b" / "bench.csv");
  EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 1 + static_cast<long>(answers.size()));  // header + answers
  fs::remove_all(dir);
}

// Where the case files come from: a folder whose cases/ lacks the question's case file is bad
// input (exit 2, naming the file) and leaves the runs saved there and bench.json as they were;
// a folder without cases/ reads the shipped ones, and the saved runs are read back.
TEST(BenchCommand, MissingCaseFileIsRefusedWithoutTouchingSavedRuns) {
  const fs::path dir = scratch_folder("feedflow_bench", true);
  const std::string args = "bench --quick --rungs L0 --only hopper_discharge_rate_60mm --out b";
  ASSERT_EQ(run_feedflow(args, dir).exit_code, 0);
  const std::string table = slurp(dir / "b" / "bench.json");
  std::map<fs::path, std::string> saved;
  for (const auto& run : fs::recursive_directory_iterator(dir / "b" / "runs"))
    if (run.path().filename() == "run.json") saved[run.path()] = slurp(run.path());
  ASSERT_EQ(saved.size(), 4u);
  fs::remove(dir / "cases" / "pilot_hopper.toml");
  const feedflow::testing::Run refused = run_feedflow(args, dir);
  EXPECT_EQ(refused.exit_code, 2);
  EXPECT_NE(refused.err.find("pilot_hopper.toml"), std::string::npos) << refused.err;
  EXPECT_EQ(slurp(dir / "b" / "bench.json"), table);
  for (const auto& [path, text] : saved) EXPECT_EQ(slurp(path), text) << path;
  fs::remove_all(dir / "cases");
  const feedflow::testing::Run shipped = run_feedflow(args, dir);
  ASSERT_EQ(shipped.exit_code, 0) << shipped.err;
  EXPECT_NE(shipped.out.find("0 run(s) made, 4 read back"), std::string::npos) << shipped.out;
  fs::remove_all(dir);
}

// An unknown question or rung is bad input (exit 2) naming the option, and nothing is written.
TEST(BenchCommand, UnknownQuestionIsRefusedByName) {
  const fs::path dir = scratch_folder("feedflow_bench", true);
  const feedflow::testing::Run r = run_feedflow("bench --only no_such_question --out b", dir);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("--only"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("hopper_discharge_rate_60mm"), std::string::npos) << r.err;  // lists the known ones
  EXPECT_FALSE(fs::exists(dir / "b"));
  EXPECT_EQ(run_feedflow("bench --rungs L7", dir).exit_code, 2);
  fs::remove_all(dir);
}

// --finest-cell leaves the CEL points on finer cells unrun ("not run" in the table) and runs the
// coarser ones: on the 37 deg plane, 40 mm is coarser than every level (20 mm down), so the CEL
// rung makes no run at all; a finest cell without a length unit is refused (exit 2, nothing
// written).
TEST(BenchCommand, FinestCellLeavesFinerCelPointsUnrun) {
  const fs::path dir = scratch_folder("feedflow_bench", true);
  const feedflow::testing::Run bad = run_feedflow(
      "bench --rungs L2 --only chute_stopping_thickness_37 --finest-cell 5 --out b", dir);
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_NE(bad.err.find("--finest-cell"), std::string::npos) << bad.err;
  EXPECT_FALSE(fs::exists(dir / "b"));
  const feedflow::testing::Run r = run_feedflow(
      "bench --rungs L2 --only chute_stopping_thickness_37 --finest-cell 40mm --out b", dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("0 run(s) made, 0 read back"), std::string::npos) << r.out;
  const auto answers =
      nlohmann::json::parse(slurp(dir / "b" / "bench.json"))["questions"][0]["answers"];
  int cel = 0;
  for (const auto& a : answers)
    if (a["rung"] == "L2") {
      ++cel;
      EXPECT_EQ(a["status"], "not run") << a.dump();
    }
  EXPECT_GE(cel, 4);  // 20, 10, 5, 2.5 mm and finer
  fs::remove_all(dir);
}

// --matching runs only the points whose command holds the text: the 37 deg plane's model
// alternatives named by "stopping_thickness=" are run (two L0 points), every other point of the
// question (the L1 deposit, CEL levels, the DEM runs) stays "not run"; --list shows just those.
TEST(BenchCommand, MatchingRunsOnlyThePointsWhoseCommandHoldsTheText) {
  const fs::path dir = scratch_folder("feedflow_bench", true);
  const std::string only = "--only chute_stopping_thickness_37 --matching stopping_thickness=";
  const feedflow::testing::Run listed = run_feedflow("bench --list " + only, dir);
  ASSERT_EQ(listed.exit_code, 0) << listed.err;
  EXPECT_EQ(std::count(listed.out.begin(), listed.out.end(), '\n'), 3) << listed.out;
  const feedflow::testing::Run r = run_feedflow("bench " + only + " --out b", dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("2 run(s) made, 0 read back"), std::string::npos) << r.out;
  int run = 0, not_run = 0;
  const auto table = nlohmann::json::parse(slurp(dir / "b" / "bench.json"));
  for (const auto& a : table["questions"][0]["answers"])
    (a["status"] == "not run" ? not_run : run) += 1;
  EXPECT_EQ(run, 2);
  EXPECT_GE(not_run, 10);
  fs::remove_all(dir);
}

}  // namespace

namespace {

// One real bench question end to end (label long, about 20 s on 2 cores): the quick points of
// the discharge rate at 60 mm give a CEL reference at 10 mm cells (3 across the half outlet;
// 20 mm cells, 1.5 across, are a point but not the reference), and every reduced model has an
// error against it, the published band of the pilot rig (seed: about 3-6 kg/s) holding it.
TEST(BenchCommand, LONG_DischargeRateQuestionEndToEnd) {
  const fs::path dir = scratch_folder("feedflow_bench", true);
  const feedflow::testing::Run r =
      run_feedflow("bench --quick --only hopper_discharge_rate_60mm --out b --report", dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto q = nlohmann::json::parse(slurp(dir / "b" / "bench.json"))["questions"][0];
  const double reference = q["reference"]["value"].get<double>();
  EXPECT_GT(reference, 3.0);
  EXPECT_LT(reference, 8.0);
  int errors = 0;
  for (const auto& a : q["answers"])
    if (a["rung"] == "L0") {
      ASSERT_TRUE(a["error"].is_number()) << a.dump();
      ++errors;
    }
  EXPECT_EQ(errors, 4);
  EXPECT_TRUE(fs::exists(dir / "b" / "report.pdf"));
  fs::remove_all(dir);
}

}  // namespace
