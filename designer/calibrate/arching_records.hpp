#pragma once
// The critical outlet widths an arching calibration fits: read from verified design records
// (results.json of `feedflow design --verify dem --width-tolerance ...`, or of a sweep point),
// each a bracket from a bisection on the outlet at one semi-angle. A record is checked to be a
// hopper of the material and the case's shape, its B_c verified on the full rung asked for.
#include <filesystem>
#include <set>
#include <string>
#include <vector>

#include "designer/calibrate/arching_fit.hpp"

namespace feedflow {

struct ArchingRecord {
  std::filesystem::path file;
  ArchingObservation observation;  // the case's hopper at the record's semi-angle and wall friction
  std::string
      rung;  // the verifying rung in words: "L3 DEM (hysteretic_nonlinear2 + k_nc cohesion)"
  std::string bracket;            // as the record says it: "arches at 31.33 mm, flows at 42.18 mm"
  std::set<std::string> commits;  // of the programs that made its runs (read from their run.json)
};

// `against`: "dem" or "cel"; `material`: the calibrated material's name; `hopper`: the case's
// hopper (its shape must be the record's). Throws InputError naming the file and the key.
ArchingRecord read_arching_record(const std::filesystem::path& file, const std::string& against,
                                  const std::string& material, const Hopper& hopper);

}  // namespace feedflow
