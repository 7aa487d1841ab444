// `feedflow simulate --report` and `feedflow report` on a simulation's results: the report carries
// pictures of the simulation itself, drawn from its snapshot files (the continuum's fields with
// its walls; the particles), and draws them again from results.json in another folder.
#include <gtest/gtest.h>

#include <cstdio>
#include <regex>

#include <nlohmann/json.hpp>

#include "fullsim/common/hdf5_file.hpp"
#include "fullsim/common/scene_outline.hpp"
#include "run_feedflow.hpp"

namespace fs = std::filesystem;
using feedflow::testing::command_output;
using feedflow::testing::pdf_text;
using feedflow::testing::run_feedflow;
using feedflow::testing::scratch_folder;
using feedflow::testing::slurp;

namespace {

// The images in a PDF of this width and height (pdfimages -list).
int images_of_size(const fs::path& pdf, int width, int height) {
  const std::string list = command_output("pdfimages -list '" + pdf.string() + "'");
  const std::regex row("image +" + std::to_string(width) + " +" + std::to_string(height) + " ");
  return static_cast<int>(
      std::distance(std::sregex_iterator(list.begin(), list.end(), row), std::sregex_iterator()));
}

int count(const std::string& text, const std::string& what) {
  int n = 0;
  for (auto at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

class SimulationReport : public ::testing::Test {
 protected:
  void SetUp() override { dir_ = scratch_folder("feedflow_simreport", true); }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path dir_;
};

// A CEL hopper run (120 mm outlet on 20 mm cells: 3 across the half outlet, seconds to run):
// its report shows the material speed at three times and the density and mean stress at the
// last (five 1000 x 600 pictures beside the reduced model's stress map), with captions naming
// the snapshot and the cell size; results.json names the run's folder; `feedflow report` from
// another folder draws the same five pictures again.
TEST_F(SimulationReport, CelHopperReportShowsItsFieldsAndIsRedrawn) {
  const auto r = run_feedflow(
      "simulate cases/pilot_hopper.toml --solver cel --time 0.15s -q --report "
      "--set hopper.outlet_width=120mm --set cel.cell_size=20mm --out run",
      dir_);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(images_of_size(dir_ / "run/report.pdf", 1000, 600), 5);
  const std::string text = pdf_text(dir_ / "run/report.pdf");
  EXPECT_EQ(count(text, "CEL material speed at t ="), 3) << text;
  EXPECT_NE(text.find("on 20 mm cells"), std::string::npos);
  EXPECT_NE(text.find("CEL bulk density"), std::string::npos);
  EXPECT_NE(text.find("CEL mean stress"), std::string::npos);
  const auto json = nlohmann::json::parse(slurp(dir_ / "run/results.json"));
  EXPECT_EQ(json.at("provenance").at("simulation_runs"), nlohmann::json::array({"."}));
  // The run's performance block: its throughput, and phases that add up to no more than the run.
  const auto& performance = json.at("performance").at(0);
  EXPECT_NE(performance.at("figures").at("throughput").get<std::string>().find("cell updates/s"),
            std::string::npos);
  double phases = 0.0;
  for (const auto& [name, seconds] : performance.at("phases_s").items())
    phases += seconds.get<double>();
  EXPECT_GT(phases, 0.5 * performance.at("wall_s").get<double>());
  EXPECT_LE(phases, performance.at("wall_s").get<double>() * (1 + 1e-9));
  EXPECT_LE(performance.at("wall_s").get<double>(), json.at("timing").at("wall_s").get<double>());
  EXPECT_NE(text.find("Performance: CEL-FEM run"), std::string::npos);

  const auto again = run_feedflow("report run/results.json --out elsewhere -q", dir_);
  ASSERT_EQ(again.exit_code, 0) << again.err;
  EXPECT_EQ(images_of_size(dir_ / "elsewhere/report.pdf", 1000, 600), 5);
  EXPECT_EQ(again.err.find("warning"), std::string::npos) << again.err;
}

// A DEM drum run (the reduced twin of the DEM scene tests): three pictures of the particles by
// speed; the snapshot file keeps the shell's outline, a circle of the drum's radius (145 mm
// drum) around its axis, so the picture draws the shell.
TEST_F(SimulationReport, DemDrumReportShowsTheParticlesInTheirShell) {
  const auto r = run_feedflow(
      "simulate cases/rotating_drum_20rpm.toml --solver dem -q --time 0.2s --report"
      " --set dem.slab_depth=18mm --set dem.normal_law=hertz"
      " --set material.dem.particle.radius=3mm --out run",
      dir_);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(images_of_size(dir_ / "run/report.pdf", 1000, 600), 3);
  const std::string text = pdf_text(dir_ / "run/report.pdf");
  EXPECT_EQ(count(text, "DEM particles coloured by speed at t ="), 3) << text;
  EXPECT_NE(text.find("particle-steps/s"), std::string::npos)
      << "the performance block is in the report";
  const auto json = nlohmann::json::parse(slurp(dir_ / "run/results.json"));
  for (const char* phase : {"pairs", "neighbours", "walls", "integration"})
    EXPECT_GT(json.at("performance").at(0).at("phases_s").at(phase).get<double>(), 0.0) << phase;
  const feedflow::Hdf5File f(dir_ / "run/particles.h5", feedflow::Hdf5File::Mode::read);
  const auto outline = feedflow::read_outline(f, "/outline");
  ASSERT_GE(outline.size(), 32u);
  for (const auto& s : outline) EXPECT_NEAR(std::hypot(s.a.x(), s.a.z()), 0.0725, 1e-9);
}

// A DEM hopper run (the small twin of the CLI tests) that empties within the run: the pictures
// are of snapshots that hold particles (none of the emptied hopper), by speed and by the layer
// each particle started in (the flow pattern), at the same three times.
TEST_F(SimulationReport, DemHopperReportShowsSpeedAndLayers) {
  fs::copy_file(fs::path(FEEDFLOW_SOURCE_DIR) / "tests/data/dem_hopper_twin.toml",
                dir_ / "twin.toml");
  const auto r =
      run_feedflow("simulate twin.toml --solver dem --time 0.5s --out run -q --report", dir_);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(images_of_size(dir_ / "run/report.pdf", 1000, 600), 6);
  const std::string text = pdf_text(dir_ / "run/report.pdf");
  EXPECT_EQ(count(text, "DEM particles coloured by speed"), 3) << text;
  EXPECT_EQ(count(text, "DEM particles coloured by the layer they started in"), 3) << text;
  EXPECT_EQ(text.find(" 0 particles"), std::string::npos) << text;
  // The performance block covers the fill (its steps are in the phases): the phases add up to
  // no more than the wall time, which holds the fill's time, shown on its own line.
  const auto json = nlohmann::json::parse(slurp(dir_ / "run/results.json"));
  const auto& performance = json.at("performance").at(0);
  const double wall = performance.at("wall_s").get<double>();
  double phases = 0.0;
  for (const auto& [name, seconds] : performance.at("phases_s").items())
    phases += seconds.get<double>();
  EXPECT_GT(phases, 0.5 * wall);
  EXPECT_LE(phases, wall * (1 + 1e-9));
  const std::string fill = performance.at("figures").at("fill (before the run)").get<std::string>();
  EXPECT_NE(fill.find(" s of the wall time"), std::string::npos) << fill;
  EXPECT_LT(std::stod(fill), wall);
}

// A results file whose run folder has lost its snapshots still gives a report (no pictures of the
// run), and one whose snapshot file is damaged gives the report with a warning naming the run.
TEST_F(SimulationReport, MissingOrDamagedSnapshotsLeaveTheReportWithoutThem) {
  ASSERT_EQ(run_feedflow("simulate cases/pilot_hopper.toml --solver cel --time 0.05s -q "
                         "--set hopper.outlet_width=120mm --set cel.cell_size=20mm --out run",
                         dir_)
                .exit_code,
            0);
  fs::rename(dir_ / "run/fields.h5", dir_ / "run/fields.h5.kept");
  const auto without = run_feedflow("report run/results.json --out a -q", dir_);
  ASSERT_EQ(without.exit_code, 0) << without.err;
  EXPECT_EQ(images_of_size(dir_ / "a/report.pdf", 1000, 600), 0);
  {
    std::FILE* damaged = std::fopen((dir_ / "run/fields.h5").c_str(), "wb");
    std::fputs("not an HDF5 file", damaged);
    std::fclose(damaged);
  }
  const auto broken = run_feedflow("report run/results.json --out b -q", dir_);
  ASSERT_EQ(broken.exit_code, 0) << broken.err;
  EXPECT_TRUE(fs::exists(dir_ / "b/report.pdf"));
  EXPECT_NE(broken.err.find("no pictures of the run in"), std::string::npos) << broken.err;
}

}  // namespace
