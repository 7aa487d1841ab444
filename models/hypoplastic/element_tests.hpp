#pragma once
// The standard laboratory element tests as loading stages for the driver, and the numbers an
// engineer reads off them: peak friction angle, critical stress ratio, critical void ratio, K0,
// the start tangent stiffness. All stages strain at unit rate (1/s), so time = strain.
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "models/hypoplastic/element_test_driver.hpp"

namespace feedflow {

enum class ElementTestKind {
  isotropic_compression,  // D = -(1/3) I: strain = volumetric strain
  oedometric,             // D_zz = -1 to `strain`, then unloading to the initial T_zz
  triaxial_compression,   // D_zz = -1, lateral stresses constant (drained)
  triaxial_extension,     // D_zz = +1, lateral stresses constant (drained)
  simple_shear,           // shear rate 1 (D_xy = W_xy = 1/2), normal stress T_yy constant
  cyclic_oedometric,      // `cycles` x (load by `strain`, unload to the initial T_zz)
};

struct ElementTestSetup {
  ElementTestKind kind = ElementTestKind::triaxial_compression;
  double strain = 0.2;  // axial (log) strain, volumetric strain (isotropic) or shear strain gamma
  int cycles = 3;       // cyclic oedometer only
  int samples = 200;    // output points per loading stage
};

// Names as the command line spells them: "isotropic", "oedometric", "triaxial" (also
// "triaxial_compression"), "triaxial_extension", "simple_shear", "cyclic_oedometric".
std::string_view element_test_name(ElementTestKind kind);
std::optional<ElementTestKind> element_test_kind(std::string_view name);
std::span<const std::string_view> element_test_names();

// Isotropic initial state T = -p0 I, e = e0.
MaterialPointState isotropic_state(double mean_pressure, double void_ratio);

// Throws std::invalid_argument for strain <= 0, cycles < 1 or samples < 1.
std::vector<LoadingStage> loading_stages(const ElementTestSetup& setup,
                                         const MaterialPointState& initial);

struct ElementTestSummary {
  double peak_friction_angle = 0.0;    // largest mobilised friction angle on the path [rad]
  double final_stress_ratio = 0.0;     // q/p at the end [-]
  double critical_stress_ratio = 0.0;  // M_c (M_e in extension) of phi_c [-]
  double final_mean_pressure = 0.0;    // [Pa]
  double final_void_ratio = 0.0;       // [-]
  double critical_void_ratio = 0.0;    // e_c at the final mean pressure [-]
  double at_rest_ratio = 0.0;          // K0 of the model at the initial p and e [-]
  double initial_stiffness = 0.0;      // start tangent stiffness [Pa]
  std::string stiffness_name;          // which one ("E", "M", "K", "G") and its definition
};

ElementTestSummary summarize_element_test(const HypoplasticModel& model,
                                          const ElementTestSetup& setup,
                                          std::span<const ElementTestSample> path);

}  // namespace feedflow
