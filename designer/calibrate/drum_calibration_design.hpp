#pragma once
// The design of experiments of a drum calibration: drum speeds of one drum case (some held out of
// the fit), each answered by a full rung as `feedflow bench` answers the seed drum's angle of
// repose: the CEL refinement series that resolves the drum's radius (Richardson), or the DEM run
// with the seed's law. Each point is the bench's own question at that speed, so runs the bench
// made are read back, and the reference is the bench's.
#include <string>
#include <vector>

#include "designer/bench/bench_plan.hpp"

namespace feedflow {

struct DrumDesignPoint {
  double speed;   // [rad/s]
  bool held_out;  // left out of the fit, to test it
};

struct DrumCalibrationDesign {
  std::string case_file;        // the drum case whose speed is varied
  std::string material;         // set on the case when the case names another; empty: the case's
  std::string against = "cel";  // "cel" | "dem"
  std::vector<DrumDesignPoint> points;
  double finest_cell = 5e-3;  // [m] the finest CEL level (the bench's drum table went to 5 mm)

  // Throws InputError (naming the flag) for fewer than two fitted speeds, a speed not above 0, or
  // a finest cell that leaves fewer than two CEL levels.
  void check() const;
};

// The fitted speeds plus the held-out ones.
std::vector<DrumDesignPoint> speed_points(const std::vector<double>& speeds,
                                          const std::vector<double>& held_out);

// "12.5": the speed in rpm as the bench's question names it.
std::string rpm_text(double speed);

// The point as the bench's drum question at its speed ("drum_angle_12.5rpm"), on the design's
// case and material, keeping the rung's reference runs only: the CEL levels that resolve the
// radius down to the finest cell, or the DEM reference.
BenchQuestion drum_point_question(const DrumCalibrationDesign& design,
                                  const DrumDesignPoint& point);

}  // namespace feedflow
