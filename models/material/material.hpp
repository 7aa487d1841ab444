#pragma once
// A bulk solid as feedflow knows it: bulk properties for the reduced models, the hypoplastic
// parameters for the continuum rung and the DEM parameters for the particle rung, each value
// with its source. Sections a material file leaves out are empty; a model that needs one says so.
#include <map>
#include <optional>
#include <set>
#include <span>
#include <string>
#include <vector>

#include "models/core/field_spec.hpp"
#include "models/material/calibration.hpp"
#include "models/material/dem_parameters.hpp"
#include "models/material/flow_properties.hpp"
#include "models/material/hypoplastic_parameters.hpp"

namespace feedflow {

struct BulkProperties {
  double density = 0.0;                       // design bulk density [kg/m^3]
  std::optional<double> loose_density;        // poured, unconsolidated [kg/m^3]
  double wall_friction_angle = 0.0;           // on the reference wall [rad]
  std::optional<double> moisture_content;     // mass fraction, wet basis [-]
};

struct ParticleSizeDistribution {
  double d10 = 0.0;  // [m], 10 % passing
  double d50 = 0.0;  // [m], median
  double d90 = 0.0;  // [m], 90 % passing
};

struct Material {
  std::string name;
  std::string description;
  std::string origin;  // the file it came from, or "built-in"
  BulkProperties bulk;
  std::optional<ParticleSizeDistribution> psd;
  std::optional<HypoplasticParameters> hypoplastic;
  std::optional<DemParameters> dem;
  std::optional<FlowProperties> flow;              // [flow_properties]
  std::optional<SurfaceFlowProperties> surface_flow;  // [surface_flow]
  std::optional<DrumFlowProperties> drum_flow;     // [drum_flow]
  std::optional<Calibration> calibration;          // [calibration], written by `feedflow calibrate`
  std::map<std::string, std::string> sources;  // dotted key ("bulk.density") -> source
  std::set<std::string> overridden;            // dotted keys a case file or --set changed
};

std::span<const FieldSpec<BulkProperties>> bulk_fields();
std::vector<FieldProblem> check(const BulkProperties& bulk);
std::span<const FieldSpec<ParticleSizeDistribution>> psd_fields();
std::vector<FieldProblem> check(const ParticleSizeDistribution& psd);

}  // namespace feedflow
