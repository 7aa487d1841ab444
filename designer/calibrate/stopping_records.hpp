#pragma once
// The stopping thicknesses a chute calibration can fit without running the plane's angles itself:
// read from verified design records of an inclined plane (results.json of `feedflow design PLANE
// --set chute.angle=A --verify dem`, or of a sweep point), each h_stop bracketed at one angle by a
// bisection of DEM stopping layers. A record is checked to be a chute of the calibrated material
// whose stopping thickness the particle rung bracketed: to the search's tolerance
// (results.stopping_thickness on L3) or, for a search cut short, as far as its layers went
// (results.stopping_thickness_so_far), a wider bracket that is no less true.
#include <filesystem>
#include <optional>
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
  bool so_far = false;  // the bracket of a search cut short, wider than its tolerance
  // [m] the spheres' radius of its runs, when the record gives it
  std::optional<double> sphere_radius;
  std::string law;      // the DEM normal law's keyword: "hysteretic_nonlinear2"
  std::string rung;     // in words: "L3 DEM (hysteretic_nonlinear2) periodic layers"
  std::string command;  // the command that verified it (its provenance), or the file's name
  std::set<std::string> commits;  // of the programs that made its layers (their run.json)
};

// `material`: the calibrated material's name; `option` the flag that named the file. Throws
// InputError naming the file and the key.
StoppingRecord read_stopping_record(const std::filesystem::path& file, const std::string& material,
                                    const std::string& option = "--stopping");

}  // namespace feedflow
