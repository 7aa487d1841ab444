#pragma once
// The design of experiments of a chute calibration: inclinations of one inclined-plane case (some
// held out of the fit), each answered by a full rung as `feedflow bench` answers the seed plane's
// deposit: the CEL refinement series down to the finest cell (Richardson), or h_stop on the
// particle rung with the seed's law (a bisection of periodic stopping layers to one sphere,
// designer/verify/stopping_verification.hpp). The deposit a CEL level must resolve is what the rung
// finds, so the resolution is checked on the reference after the runs (`unresolved_deposit`), not
// planned from the law being calibrated.
#include <string>
#include <vector>

#include <map>

#include "designer/bench/bench_plan.hpp"
#include "designer/bench/bench_run.hpp"

namespace feedflow {

struct ChuteDesignPoint {
  double angle;   // [rad]
  bool held_out;  // left out of the fit, to test it
};

struct ChuteCalibrationDesign {
  std::string case_file;        // the inclined-plane case whose angle is varied
  std::string material;         // set on the case when the case names another; empty: the case's
  std::string against = "cel";  // "cel" | "dem"
  std::vector<ChuteDesignPoint> points;
  double finest_cell = 10e-3;  // [m] the finest CEL level

  // Throws InputError (naming the flag) for fewer than two fitted inclinations, one outside
  // (0, 90) deg, two alike, or a finest cell that leaves fewer than two CEL levels.
  void check() const;
};

// The fitted inclinations plus the held-out ones.
std::vector<ChuteDesignPoint> inclination_points(const std::vector<double>& angles,
                                                 const std::vector<double>& held_out);

// "33.5": the inclination in degrees as the question names it.
std::string degrees_text(double angle);

// The point as a bench deposit question at its inclination ("chute_deposit_33.5deg"), on the
// design's case and material, keeping the rung's reference runs only: every CEL level from
// 20 mm down to the finest cell, or the DEM reference (the stopping layers' bisection).
BenchQuestion chute_point_question(const ChuteCalibrationDesign& design,
                                   const ChuteDesignPoint& point);

// Takes out of the reference every CEL level whose own deposit (in `runs`, by point_id) has
// fewer than kReferenceCellsAcross cells across it (it cannot resolve what it answers), and
// returns why the point has no reference when fewer than two levels at rest are left of a CEL
// series; empty otherwise (and for DEM).
std::string keep_resolving_levels(BenchQuestion& question,
                                  const std::map<std::string, BenchRun>& runs);

}  // namespace feedflow
