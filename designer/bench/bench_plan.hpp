#pragma once
// What `feedflow bench` measures: the design questions of the seed's scenes (a case, the
// setting that poses the question, the result it reads) and, for each, the points to run: every
// rung and setting a user or the designer could choose (each reduced-model alternative, CEL at
// each cell size, DEM with each normal law), and the runs that make its reference (a CEL
// refinement series, the DEM run at the seed's resolution). `quick` points are the coarse ones
// (`feedflow bench --quick`, minutes); the rest take hours.
#include <optional>
#include <string>
#include <vector>

#include "designer/simulate/simulation_request.hpp"

namespace feedflow {

// The role of a point in the question's reference.
enum class ReferenceRole {
  none,            // measured against the reference
  cel_refinement,  // one level of the CEL refinement series (Richardson)
  dem_reference,   // the DEM run at the seed's resolution with the seed's law
};

struct BenchPoint {
  std::string setting;               // what a user would choose: "CEL 10 mm cells"
  std::string rung;                  // "L0", "L1", "L2", "L3"
  std::string quantity;              // the results key this point answers with
  std::optional<Solver> solver;      // none: the design check (reduced models)
  // "dem": the design check verified on that rung (`design --verify dem`: the critical outlet
  // width bracketed by a bisection of DEM runs, each flowing or arching, to `width_tolerance`; a
  // chute's h_stop by one of DEM stopping layers, each resting or flowing, to
  // `thickness_tolerance`).
  std::string verify;
  std::string width_tolerance;       // as typed: "2.5mm"
  std::string thickness_tolerance;   // as typed: "3mm"
  std::vector<std::string> sets;     // --set KEY=VALUE beyond the question's own
  std::vector<std::string> models;   // --model KEY=NAME
  std::optional<double> time;        // [s] simulated time (--time); none: the scene's own end
  std::optional<double> cell_size;   // [m] of a CEL point (h of the refinement series' levels)
  ReferenceRole role = ReferenceRole::none;
  bool quick = false;
  // A number read as the question's label (the arching question reads B_c against the outlet):
  // above `threshold` it is `above`, else `below`.
  struct LabelRule {
    double threshold = 0.0;
    std::string above, below;
  };
  std::optional<LabelRule> label_rule;
  // The results key that reads "yes" when the run ended at rest (a deposit's thickness); a run
  // that ended still flowing answers an upper bound, kept out of the reference and the ranking.
  std::string rest_key;
  // The results key whose value is the half-width of the answer's statistical interval (the
  // 95 % interval of a time average's mean: the drum's angle); the point's own quantity: its
  // band is that interval (the hopper's rate); empty: none (a deposit, a label).
  std::string interval_key;
  std::string resolution;            // what a CEL point resolves: "3 cells across the half outlet"
};

struct BenchQuestion {
  std::string id;                    // "hopper_discharge_rate_60mm" (file-name friendly)
  std::string title;                 // "Pilot hopper: mass discharge rate at W = 60 mm"
  std::string case_file;             // relative to the repository root: "cases/pilot_hopper.toml"
  std::vector<std::string> sets;     // the question's setting: "hopper.outlet_width=60mm"
  bool categorical = false;          // a label (arching, regime), judged right or wrong
  std::vector<BenchPoint> points;
  // The order two CEL levels extrapolate with, and where it was measured; none: the donor-cell
  // remap's formal order 1.
  std::optional<double> two_level_order;
  std::string two_level_order_source;
};

// A CEL level enters the reference only when it puts at least this many cells across the
// feature the question turns on (half the outlet, the drum's radius, the deposit): coarser
// runs are bench points, shown with their error, but cannot resolve the answer (a 60 mm
// outlet on 20 mm cells reads "arched" for a hopper that flows).
constexpr double kReferenceCellsAcross = 3.0;

// A full-rung run a verification makes, as a bench question (`id`) so that a second call reads
// it back: the case as typed with its `sets` and one `set` more ("hopper.outlet_width=38mm").
BenchQuestion verification_run_question(std::string id, std::string case_file,
                                        std::vector<std::string> sets, std::string set);
// Its DEM point: `setting` names it, the answer is read from the results key `quantity`.
BenchPoint dem_verification_point(std::string setting, std::string quantity);

// "2.5mm": a length as typed after --set (no space: an invocation is a runnable command).
std::string millimetres_setting(double metres);

// `text` as one file name: anything but letters, digits, '.' and '-' becomes '_'.
std::string file_name_friendly(std::string text);
// A point's identity in the question: "<rung>_<setting>", file-name friendly.
std::string point_id(const BenchPoint& point);

// The questions of the seed's scenes with all their points (pilot hopper, inclined plane, drum).
std::vector<BenchQuestion> seed_bench_questions();

// A deposit-thickness question on an inclined-plane case (its `sets` pose it: "chute.angle=33deg"),
// on every rung and setting: the stopping-thickness and deposit models, CEL levels (those with
// at least kReferenceCellsAcross cells across `deposit` [m] make the reference; the first
// `quick_levels` are quick) and DEM with each law.
BenchQuestion chute_question(std::string id, std::string title, std::string case_file,
                             std::vector<std::string> sets, double deposit, int quick_levels);

// The seed drum (cases/rotating_drum_20rpm.toml) at `rpm` ("10", "12.5"): its angle of repose
// or its regime, on every rung and setting, as the bench asks it.
BenchQuestion drum_question(const std::string& rpm, bool regime);

}  // namespace feedflow
