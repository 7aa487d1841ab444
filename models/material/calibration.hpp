#pragma once
// A material's [calibration] table: reduced-model coefficients that `feedflow calibrate` fitted
// to a full rung over a design of experiments, with what they were fitted to (rung, scene,
// commit, date) and how well (residuals before and after, on the fitted and the held-out points).
// The design check uses them for hoppers of the calibrated geometry and says so. A drum
// calibration ([calibration.drum]), an arching one ([calibration.arching]) and a chute one
// ([calibration.chute]) have their own provenance: each is made and written apart.
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace feedflow {

// One model row's fit: its coefficients by name, and the fit's figures as text with units
// ("4.1 %"), kept for the report.
struct CalibratedModel {
  std::map<std::string, double> coefficients;
  std::map<std::string, std::string> figures;  // fit_rms_error, held_out_max_error, before_...
};

// The figure `name` of `m` as a fraction ("6.32 %" -> 0.0632); none when absent or not a
// percentage.
std::optional<double> percent_figure(const CalibratedModel& m, const std::string& name);
// The largest of the fit's errors (fit_rms_error, held_out_max_error) as a fraction; none
// without either.
std::optional<double> largest_error(const CalibratedModel& m);

// The drum's flowing layer (drum_check, reduced_models.md section 4) fitted to a rung's angles
// of repose over drum speeds: coefficients "layer_fraction" (c_delta) and "friction_shift" [rad]
// (added to the Pouliquen angles theta1 and theta2 the layer's mu(I) is matched to).
struct DrumCalibration {
  std::string against;  // "cel" | "dem"
  std::string rung;     // what the references were, in words
  std::string scene;    // the drum case whose speed the design of experiments varied
  bool end_walls = false;  // the rung's drum had end walls (the fit kept mu_ew; a slice: none)
  // The calibrated drum's size and fill: a drum far from them extrapolates the fit (tables
  // written before they were recorded have none).
  std::optional<double> diameter;       // [m]
  std::optional<double> fill_fraction;  // [-]
  std::string commit, date;  // of the program that made the references
  CalibratedModel layer;
  std::size_t points = 0;  // design points (fitted and held out)
};

// The flow function's strength in the arching models fitted to a rung's critical outlet widths
// (each a bracket from a bisection on the outlet, `design --verify dem --width-tolerance`):
// coefficient "strength_scale" per hopper.critical_outlet row, multiplying sigma_c in that row's
// B_c, evaluated with the flow-factor row `flow_factor`.
struct ArchingCalibration {
  std::string against;       // "dem" (a rung that arches)
  std::string rung;          // what the references were, in words (the law and its cohesion)
  std::string scene;         // the hopper case the bisections ran on
  std::string geometry;      // "wedge" | "conical"
  std::string flow_factor;   // the hopper.flow_factor row the fit evaluated B_c with
  std::string commit, date;  // of the program that made the references
  std::map<std::string, CalibratedModel> rows;  // by hopper.critical_outlet row name
  std::size_t points = 0;                       // semi-angles bracketed (fitted and held out)
};

// Pouliquen's stopping-thickness law fitted to a rung's deposits on an inclined plane over its
// inclination: coefficients "theta2" [rad] and "stop_length" [m] (L), and "theta1" [rad] when
// it was fitted too (else the material's holds: every layer static below it). The chute check
// uses them instead of the material's [surface_flow] ones; the drum's flowing layer keeps the
// material's.
struct ChuteCalibration {
  std::string against;  // "cel" | "dem"
  std::string rung;     // what the references were, in words
  std::string scene;    // the plane case whose inclination the design of experiments varied
  double lowest_angle = 0.0, highest_angle = 0.0;  // [rad] the fitted inclinations' range
  std::string commit, date;                        // of the program that made the references
  CalibratedModel law;
  std::size_t points = 0;  // design points (fitted and held out)
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
  std::optional<DrumCalibration> drum;  // [calibration.drum]
  std::optional<ArchingCalibration> arching;  // [calibration.arching]
  std::optional<ChuteCalibration> chute;      // [calibration.chute]
};

}  // namespace feedflow
