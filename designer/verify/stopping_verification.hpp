#pragma once
// Verifying a chute's stopping thickness on the particle rung (L3), for `design --verify dem`:
// h_stop at the chute's angle bracketed by a bisection on the thickness of periodic stopping
// layers (threshold_bisection.hpp), each a DEM run of the case with [dem] stopping_layer, as
// `feedflow simulate --solver dem` runs it: a layer that comes to rest is at most h_stop, one
// that still flows at the run's end is above it. The search starts in the reduced rung's band
// and widens beyond it (down to one sphere, up to kLayerCeilingDiameters spheres) when an edge
// does not change the answer, so it ends with a bracket the reduced band may not hold. The seed's
// whole plane (about 180 000 of its spheres, 100 h per angle on one thread) cannot give h_stop
// in a design's time; a layer holds about 1 100 of them for 30 mm.
#include <filesystem>
#include <iosfwd>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "designer/bench/bench_plan.hpp"
#include "designer/case/case.hpp"
#include "designer/verify/threshold_bisection.hpp"
#include "models/core/design_record.hpp"

namespace feedflow {

// The thickest layer the search may try, in sphere diameters.
constexpr double kLayerCeilingDiameters = 40.0;
// [m] every layer's thickness lies on this grid, so the search asks the same layers when it
// starts again from the thicknesses its folders are named by (a layer cut short is continued,
// not made afresh under a name a digit apart).
constexpr double kLayerGrid = 1e-6;

// The DEM layer the verification runs at `thickness` [m] as a bench question and point, so a
// second call reads it back: the case as typed with its `sets` and the thickness.
BenchQuestion layer_run_question(const std::string& case_file, const std::vector<std::string>& sets,
                                 double thickness);
BenchPoint layer_run_point();

struct StoppingVerificationPlan {
  std::string law;  // the DEM normal law's keyword
  // [m] the reduced rung's h_stop band (none without one: above theta2 it leaves no layer)
  std::optional<double> reduced_low, reduced_high;
  double low = 0.0, high = 0.0;       // [m] the band searched first: the reduced one, at least a
                                      // sphere up and two tolerances wide
  double floor = 0.0, ceiling = 0.0;  // [m] how far it may widen: one sphere, the ceiling
  double tolerance = 0.0;             // [m]
  int runs = 0;                       // layers judged when the band holds h_stop
  double seconds = 0.0;               // [s] their estimate (at the band's middle)
  std::string cost;                   // "about 1 h 05 min on 2 cores: ..."
};

// The plan for the chute case and the record of its design check; `tolerance` [m], 0: one
// sphere diameter (a layer's thickness is read to about one). Throws InputError naming
// --thickness-tolerance when it is negative or above a quarter of the layers' range, and --verify
// when the material has no [dem] table.
StoppingVerificationPlan plan_stopping_verification(const Case& c, const DesignRecord& record,
                                                    double tolerance);

struct StoppingVerification {
  ThresholdBisection bisection;
  std::string status = "done";  // or why it stopped
  double wall_seconds = 0.0;    // [s] of the runs made now
  double seconds_needed = 0.0;  // [s] the estimate of the layers still to make, when the budget
                                // refused them (0 otherwise)
  // [m] the thickness the thickest layer that came to rest measured at its end (trimmed to
  // bisection.stops_at)
  std::optional<double> rested_thickness;
  std::filesystem::path last_run;  // the folder of the last layer judged
};

// Layers judged by an earlier search at this angle whose runs are not here (another machine's,
// say), as its record gives them: thickness [m] -> flows.
using EarlierLayers = std::map<double, bool>;

// Runs the plan below `runs_folder` (runs already there are read back, and layers kept from any
// earlier search at this angle, in the folder or `earlier`, narrow the band it starts from;
// `earlier` answer for their thickness without a run); the plan's estimate must fit
// `budget_seconds`, less what the layers kept already answer, or none is started and the status
// says what it would take (the bisection then holds the layers kept).
StoppingVerification verify_stopping(const std::string& case_file,
                                     const std::vector<std::string>& sets,
                                     const StoppingVerificationPlan& plan, double budget_seconds,
                                     const std::filesystem::path& runs_folder,
                                     std::ostream* progress, const EarlierLayers& earlier = {});

// The record with the particle rung's h_stop bracket in place of the reduced stopping thickness
// (kept beside it), judged again; a note says verified (the bracket meets the reduced band) or
// contradicted (it lies outside it), with the layers and the runs' time. A search cut short with
// a layer at rest below one that flows leaves its bracket so far beside the reduced one
// (stopping_thickness_so_far, not judged), where `--start-from` and `calibrate --stopping` read
// it.
void apply_stopping_verification(const Case& c, const StoppingVerificationPlan& plan,
                                 const StoppingVerification& v, DesignRecord& record);

}  // namespace feedflow
