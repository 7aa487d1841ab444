// The pilot wedge hopper slab against its LIGGGHTS 3.8 twin (tests/benchmarks/peers/
// in.hopper_slab.liggghts, README.md there): the same grains (the peer started from our settled
// fill at the opening), Hertz with the same dashpot, 3.3 mm slab between frictionless faces,
// the same sink 5 R below the outlet, the same dt; both rates measured by our steady-window
// rule (50 ms batches, MSER truncation). The peer's discharge series is kept in
// tests/data/peers/hopper_slab_liggghts.csv.
#include <gtest/gtest.h>

#include <stdlib.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "designer/simulate/hopper_discharge.hpp"
#include "run_feedflow.hpp"

namespace fs = std::filesystem;
using feedflow::testing::run_feedflow;
using feedflow::testing::scratch_folder;
using feedflow::testing::slurp;

namespace {

// The peer run (LIGGGHTS-PUBLIC 3.8.0, Debian 3.8.0+repack1-9+b2, one MPI rank; 2026-12-02,
// branch slabfaces from main d4ca265): 29 617 grains at the opening, dt = 1.6003219e-5 s,
// 1.5 s after the opening. Its steady rate by our rule over the first kOurRunLength of it (our
// run stops there, converged), per slab [kg/s] with its 95 % interval: 0.02910 kg/s
// (0.02804-0.03017) over 0.2-0.5 s after the opening, 6 batches of 50 ms.
constexpr double kOurRunLength = 0.5502;  // [s] after the opening
constexpr double kPeerRate = 0.029104710220533354;
constexpr double kPeerLow = 0.028039687284283996, kPeerHigh = 0.030169733156782712;
constexpr double kPeerWindowStart = 0.2, kPeerWindowEnd = 0.5;  // [s] after the opening
constexpr std::size_t kPeerGrains = 29617;

// The peer's series: time after the opening [s], discharged mass [kg], grains in the domain.
// Rows up to `until` [s].
feedflow::HopperDischarge::Rows peer_rows(std::size_t& first_grains, double until) {
  std::ifstream in(fs::path(FEEDFLOW_TEST_DATA_DIR) / "peers/hopper_slab_liggghts.csv");
  feedflow::HopperDischarge::Rows rows;
  std::string line;
  first_grains = 0;
  rows.time.push_back(0.0);
  rows.discharged.push_back(0.0);
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream s(line);
    double t = 0.0, m = 0.0, n = 0.0;
    s >> t >> m >> n;
    if (t > until) break;
    if (first_grains == 0) first_grains = static_cast<std::size_t>(n);
    rows.time.push_back(t);
    rows.discharged.push_back(m);
  }
  return rows;
}

class HopperSlabPeerTwin : public ::testing::Test {
 protected:
  void SetUp() override { dir_ = scratch_folder("feedflow_peertwin", true); }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path dir_;
};

// The peer's numbers stored here are the steady window of its kept series, measured by our
// rule (the record and the series agree), and its grains are the fill's.
TEST_F(HopperSlabPeerTwin, PeerRateIsTheSteadyWindowOfItsSeries) {
  std::size_t grains = 0;
  const auto rows = peer_rows(grains, kOurRunLength);
  ASSERT_EQ(rows.time.size(), 56u);
  EXPECT_EQ(grains, kPeerGrains);
  const feedflow::SteadyRate r = feedflow::HopperDischarge{}.steady_rate(rows);
  ASSERT_TRUE(r.found);
  std::printf("peer: %s\n", r.describe().c_str());
  EXPECT_NEAR(r.rate, kPeerRate, 1e-6);
  EXPECT_NEAR(r.low, kPeerLow, 1e-6);
  EXPECT_NEAR(r.high, kPeerHigh, 1e-6);
  EXPECT_NEAR(r.window_start, kPeerWindowStart, 1e-9);
  EXPECT_NEAR(r.window_end, kPeerWindowEnd, 1e-9);
}

// The discharged mass of our series at `t` after the opening (the row nearest to it) [kg].
double discharged_at(const std::string& csv, double t) {
  std::istringstream in(csv);
  std::string line;
  std::getline(in, line);  // header
  double best = 1e9, mass = 0.0;
  while (std::getline(in, line)) {
    std::istringstream row(line);
    std::string time, after, discharged;
    std::getline(row, time, ',');
    std::getline(row, after, ',');
    std::getline(row, discharged, ',');
    if (std::abs(std::stod(after) - t) < best) {
      best = std::abs(std::stod(after) - t);
      mass = std::stod(discharged);
    }
  }
  return mass;
}

// Our pilot slab (Hertz, 3.3 mm, frictionless faces) discharges at the LIGGGHTS twin's steady
// rate within 5 % (per slab, kg/s), from the same fill (rain seed 1): our steady rate, and our
// mean rate over the peer's steady window.
TEST_F(HopperSlabPeerTwin, LONG_PilotSlabDischargesAsLiggghts) {
  // One thread, as the run whose fill the peer started from (a run is the same to the bit for
  // a given thread count).
  setenv("OMP_NUM_THREADS", "1", 1);
  const auto r = run_feedflow(
      "simulate cases/pilot_hopper.toml --solver dem -q --set dem.normal_law=hertz "
      "--set dem.slab_depth=3.3mm --set dem.slab_faces=frictionless --out run",
      dir_);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto json = nlohmann::json::parse(slurp(dir_ / "run/results.json"));
  const auto& q = json.at("results").at("mass_flow_rate_slab");
  EXPECT_EQ(q.at("unit"), "kg/s");
  const double ours = q.at("value").get<double>();
  std::printf(
      "q_m per slab: ours %.5g kg/s (%.5g-%.5g), LIGGGHTS %.5g kg/s (%.5g-%.5g): %+.2f %%\n", ours,
      q.at("low").get<double>(), q.at("high").get<double>(), kPeerRate, kPeerLow, kPeerHigh,
      100.0 * (ours / kPeerRate - 1.0));
  EXPECT_NEAR(ours, kPeerRate, 0.05 * kPeerRate);
  const std::string csv = slurp(dir_ / "run/timeseries.csv");
  const double same_window =
      (discharged_at(csv, kPeerWindowEnd) - discharged_at(csv, kPeerWindowStart)) /
      (kPeerWindowEnd - kPeerWindowStart);
  std::printf("over the peer's window %.3g-%.3g s: ours %.5g kg/s (%+.2f %%)\n", kPeerWindowStart,
              kPeerWindowEnd, same_window, 100.0 * (same_window / kPeerRate - 1.0));
  EXPECT_NEAR(same_window, kPeerRate, 0.05 * kPeerRate);
}

}  // namespace
