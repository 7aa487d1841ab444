#pragma once
// A material's [calibration] table: reduced-model coefficients that `feedflow calibrate` fitted
// to a full rung over a design of experiments, with what they were fitted to (rung, scene,
// commit, date) and how well (residuals before and after, on the fitted and the held-out points).
// The design check uses them for hoppers of the calibrated geometry and says so.
#include <map>
#include <string>
#include <vector>

namespace feedflow {

// One model row's fit: its coefficients by name, and the fit's figures as text with units
// ("4.1 %"), kept for the report.
struct CalibratedModel {
  std::map<std::string, double> coefficients;
  std::map<std::string, std::string> figures;  // fit_rms_error, held_out_max_error, before_...
};

struct Calibration {
  std::string against;        // "cel" | "dem"
  std::string rung;           // what the references were, in words
  std::string scene;          // the case whose geometry the design of experiments varied
  std::string geometry;       // "wedge" | "conical": the hoppers the discharge coefficients apply to
  std::string density_model;  // the hopper.bulk_density row the fit evaluated the reduced models with
  std::string commit, date;   // of the program that made the references
  std::map<std::string, CalibratedModel> discharge;  // by hopper.discharge row name
  std::size_t points = 0;     // design points (fitted and held out)
};

}  // namespace feedflow
