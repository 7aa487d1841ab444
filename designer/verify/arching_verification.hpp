#pragma once
// Verifying a hopper's arching on the particle rung (L3), for `design --verify dem`: a DEM run at
// the design outlet says whether it arches, and the critical width is found by bisection on the
// outlet width (width_bisection.hpp) inside the reduced rung's band, each width a DEM run of the
// case (flows or arches, as `feedflow simulate --solver dem` measures it). Which width the runs
// verify depends on the contacts: ones that pull ([dem] cohesion = k_nc, the seed's hysteretic
// law's K_nc branch) can form cohesive arches and verify B_c inside the reduced band; ones that do
// not (cohesion none, the default as in the seed's software, or Hertz, Hooke) show interlocking
// arches only and verifies the rule (3-8) d on the DEM's spheres (a
// coarse-grained DEM's spheres are not the material's grains, so its width then stands beside
// the material's reduced one instead of replacing it). Each width has its own wedge walls, so
// its own fill: the fill cannot be reused between steps (it can only when the walls stay, as in
// a restart of the same width, which reads the run back).
#include <filesystem>
#include <iosfwd>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "designer/bench/bench_plan.hpp"
#include "designer/case/case.hpp"
#include "designer/verify/width_bisection.hpp"
#include "models/core/design_record.hpp"

namespace feedflow {

// The case with contacts that pull ([dem] cohesion = k_nc), which a cohesive B_c needs on the
// particle rung, when its normal law has a K_nc branch and the case names no cohesion of its
// own; nullopt otherwise (the case stays as written).
std::optional<Case> with_cohesive_contacts(const Case& c);

// The DEM run the verification makes at outlet width `w` [m] (the scene's own end: until it
// arches, empties or its rate has converged), as a bench question and point so a second call
// reads it back: the case as typed with its `sets` and the width.
BenchQuestion arching_run_question(const std::string& case_file,
                                   const std::vector<std::string>& sets, double w);
BenchPoint arching_run_point();

struct ArchingVerificationPlan {
  std::string quantity;  // "critical_outlet_width" (cohesive law) or "mechanical_arching_width"
  std::string law;       // the DEM normal law's keyword (+ " + k_nc cohesion" when contacts pull)
  double low = 0.0,
         high = 0.0;  // the band searched [m]: the reduced B_c band, or 3-8 sphere diameters
  double sphere_diameter = 0.0;  // [m] of the DEM's spheres (interlocking)
  double tolerance = 0.0;        // [m]
  int runs = 0;                  // DEM runs: the design outlet, then the bisection's
  // [s] the design outlet's run by its estimate, held against the budget before it is made (0:
  // not estimated, the run is made whatever the budget).
  double outlet_seconds = 0.0;
};

// The plan for the case and the record of its design check; throws InputError naming
// --width-tolerance when it is not positive, and when the record has no band to search.
ArchingVerificationPlan plan_arching_verification(const Case& c, const DesignRecord& record,
                                                  double tolerance);

// What the plan's DEM runs will cost by their estimate (dem_run_estimate.hpp): the design
// outlet's run, and each of the bisection's at the band's middle (the reduced rate scaled as
// W^1.5), every one as if it flowed until the hopper emptied (one that arches stops sooner; one
// that trickles on to the scene's end takes up to the longest, which the text states too).
struct ArchingVerificationCost {
  double seconds = 0.0;         // [s] on the bench machine's two cores
  double outlet_seconds = 0.0;  // [s] of which the design outlet's run
  std::string text;      // "about 9.1 h on 2 cores by its estimate: ..."
};
ArchingVerificationCost estimate_arching_verification(const Case& c, const DesignRecord& record,
                                                      const ArchingVerificationPlan& plan);

// The flow pattern the design outlet's DEM run read by the layer method, when it flowed long
// enough for a steady window: "mass" or "funnel", with what it was read from.
struct ParticleFlowPattern {
  std::string pattern;
  std::string model;  // "DEM (law) at the design outlet 45 mm: " + read
  std::string read;   // "wall/centre speed 0.97, FIFO index 0.97[, stagnant zone 30 mm]"
};

struct ArchingVerification {
  std::optional<OutletOutcome> at_design;  // the design outlet's run
  std::optional<ParticleFlowPattern> flow_pattern;  // of the design outlet's run
  WidthBisection bisection;
  std::string status = "done";       // or why it stopped
  double wall_seconds = 0.0;         // of the runs made now
  double seconds_needed = 0.0;       // [s] the runs still to make, when the budget refused them
  double longest_run = 0.0;          // [s] the slowest run (its time when it was made)
  std::filesystem::path design_run;  // the design outlet's run folder
};

// What an earlier record of this hopper's `--verify dem` answered (`--start-from`, its runs on
// another machine, say): the widths of its bracket (to its tolerance, or as far as a search cut
// short went) and, when it was of the same design outlet, what that run showed.
struct EarlierArching {
  std::map<double, OutletOutcome> widths;           // [m]
  std::optional<OutletOutcome> at_design;           // the design outlet's run
  std::optional<ParticleFlowPattern> flow_pattern;  // what that run read
};

// Runs the plan below `runs_folder` (runs already there are read back; `earlier` answers for its
// widths and the design outlet without a run, and its bracket is where the bisection starts). The
// design outlet's run goes first (it also verifies the flow pattern: the particle rung reads it on
// wedges and cones alike, where the continuum's cone does not converge), unless its estimate
// (plan.outlet_seconds) exceeds `budget_seconds`; its wall time, times the bisection's runs, must
// fit `budget_seconds`, or the bisection is not started and the status says what it would take.
ArchingVerification verify_arching(const std::string& case_file,
                                   const std::vector<std::string>& sets, const Hopper& hopper,
                                   const ArchingVerificationPlan& plan, double budget_seconds,
                                   const std::filesystem::path& runs_folder, std::ostream* progress,
                                   const EarlierArching& earlier = {});

// The record with the particle rung's answers in place of the reduced ones (kept beside them under
// reduced_model_key): arching at the design outlet (observed), the plan's width as the bisection's
// bracket; judged again; a note says verified (the rung's width inside the reduced band) or
// contradicted (outside it, at the edge that showed it), with the numbers and the runs. A search
// cut short with an outlet that arched below one that flowed leaves its bracket so far beside the
// reduced width (<width key>_so_far, not judged), where `--start-from` reads it.
void apply_arching_verification(const Case& c, const ArchingVerificationPlan& plan,
                                const ArchingVerification& v, DesignRecord& record);

}  // namespace feedflow
