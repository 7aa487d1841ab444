#pragma once
// The stopping thicknesses a chute calibration can fit without running the plane's angles itself:
// read from verified design records of an inclined plane (results.json of `feedflow design PLANE
// --set chute.angle=A --verify dem`, or of a sweep point), each h_stop bracketed at one angle by a
// bisection of DEM stopping layers. A record is checked to be a chute of the calibrated material
// whose stopping thickness the particle rung bracketed.
#include <filesystem>
#include <set>
#include <string>

#include "designer/calibrate/stop_law_fit.hpp"

namespace feedflow {

struct StoppingRecord {
  std::filesystem::path file;
  // The record's angle; the reference is the bracket's middle, its error bar half the bracket.
  StopObservation observation;
  double stops_at = 0.0, flows_at = 0.0;  // [m] the thickest layer that rested, the thinnest
                                          // that flowed
  std::string rung;     // in words: "L3 DEM (hysteretic_nonlinear2) periodic layers"
  std::string command;  // the command that verified it (its provenance), or the file's name
  std::set<std::string> commits;  // of the programs that made its layers (their run.json)
};

// `material`: the calibrated material's name. Throws InputError naming the file and the key.
StoppingRecord read_stopping_record(const std::filesystem::path& file, const std::string& material);

}  // namespace feedflow
