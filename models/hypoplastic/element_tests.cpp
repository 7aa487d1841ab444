#include "models/hypoplastic/element_tests.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>

#include "models/hypoplastic/at_rest_stress_ratio.hpp"
#include "models/hypoplastic/stress_invariants.hpp"
#include "models/material/bulk_compressibility.hpp"

namespace feedflow {
namespace {

constexpr int xx = 0, yy = 1, zz = 2, xy = 3;

struct NamedKind {
  std::string_view name;
  ElementTestKind kind;
};
constexpr std::array<NamedKind, 6> kKinds{{
    {"isotropic", ElementTestKind::isotropic_compression},
    {"oedometric", ElementTestKind::oedometric},
    {"triaxial", ElementTestKind::triaxial_compression},
    {"triaxial_extension", ElementTestKind::triaxial_extension},
    {"simple_shear", ElementTestKind::simple_shear},
    {"cyclic_oedometric", ElementTestKind::cyclic_oedometric},
}};
constexpr std::array<std::string_view, 6> kNames{"isotropic",         "oedometric",
                                                  "triaxial",          "triaxial_extension",
                                                  "simple_shear",      "cyclic_oedometric"};

LoadingStage strain_stage(double duration, int samples) {
  LoadingStage s;
  s.duration = duration;
  s.samples = samples;
  return s;
}

LoadingStage oedometric_stage(double axial_rate, double duration, int samples) {
  LoadingStage s = strain_stage(duration, samples);
  s.control.rate[zz] = axial_rate;
  return s;
}

// Unloading until T_zz is back at its initial value (at most `cap` of strain).
LoadingStage oedometric_unloading(double initial_axial_stress, double cap, int samples) {
  LoadingStage s = oedometric_stage(1.0, cap, samples);
  s.stop_component = zz;
  s.stop_stress = initial_axial_stress;
  return s;
}

LoadingStage triaxial_stage(double axial_rate, double duration, int samples) {
  LoadingStage s = oedometric_stage(axial_rate, duration, samples);
  s.control.control[xx] = ComponentControl::stress;
  s.control.control[yy] = ComponentControl::stress;
  return s;
}

}  // namespace

std::string_view element_test_name(ElementTestKind kind) {
  for (const auto& k : kKinds)
    if (k.kind == kind) return k.name;
  return "unknown";
}

std::optional<ElementTestKind> element_test_kind(std::string_view name) {
  if (name == "triaxial_compression") return ElementTestKind::triaxial_compression;
  for (const auto& k : kKinds)
    if (k.name == name) return k.kind;
  return std::nullopt;
}

std::span<const std::string_view> element_test_names() { return kNames; }

MaterialPointState isotropic_state(double p, double e) {
  MaterialPointState s;
  s.stress = -p * Eigen::Matrix3d::Identity();
  s.void_ratio = e;
  return s;
}

std::vector<LoadingStage> loading_stages(const ElementTestSetup& setup,
                                         const MaterialPointState& initial) {
  if (!(setup.strain > 0.0) || setup.cycles < 1 || setup.samples < 1)
    throw std::invalid_argument("element test: need strain > 0, cycles >= 1 and samples >= 1");
  const double strain = setup.strain;
  const int n = setup.samples;
  const double axial0 = initial.stress(2, 2);
  switch (setup.kind) {
    case ElementTestKind::isotropic_compression: {
      LoadingStage s = strain_stage(strain, n);
      s.control.rate[xx] = s.control.rate[yy] = s.control.rate[zz] = -1.0 / 3.0;
      return {s};
    }
    case ElementTestKind::oedometric:
      return {oedometric_stage(-1.0, strain, n), oedometric_unloading(axial0, strain, n)};
    case ElementTestKind::triaxial_compression:
      return {triaxial_stage(-1.0, strain, n)};
    case ElementTestKind::triaxial_extension:
      return {triaxial_stage(1.0, strain, n)};
    case ElementTestKind::simple_shear: {
      LoadingStage s = strain_stage(strain, n);
      s.control.rate[xy] = 0.5;  // L_xy = dv_x/dy = 1: D_xy = W_xy = 1/2
      s.control.spin(0, 1) = 0.5;
      s.control.spin(1, 0) = -0.5;
      s.control.control[yy] = ComponentControl::stress;
      return {s};
    }
    case ElementTestKind::cyclic_oedometric: {
      std::vector<LoadingStage> stages;
      for (int c = 0; c < setup.cycles; ++c) {
        stages.push_back(oedometric_stage(-1.0, strain, n));
        stages.push_back(oedometric_unloading(axial0, strain, n));
      }
      return stages;
    }
  }
  throw std::invalid_argument("element test: unknown kind");
}

ElementTestSummary summarize_element_test(const HypoplasticModel& model,
                                          const ElementTestSetup& setup,
                                          std::span<const ElementTestSample> path) {
  if (path.empty()) throw std::invalid_argument("summarize_element_test: empty path");
  ElementTestSummary s;
  for (const auto& sample : path)
    s.peak_friction_angle = std::max(s.peak_friction_angle, mobilised_friction_angle(sample.stress));
  const auto& last = path.back();
  s.final_mean_pressure = mean_pressure(last.stress);
  s.final_stress_ratio = deviatoric_stress(last.stress) / s.final_mean_pressure;
  s.final_void_ratio = last.void_ratio;
  s.critical_void_ratio =
      limit_void_ratios(model.parameters, std::max(s.final_mean_pressure, 0.0)).e_c;
  const double sin_phi = model.constants.sin_phi_c;
  s.critical_stress_ratio = setup.kind == ElementTestKind::triaxial_extension
                                ? 6.0 * sin_phi / (3.0 + sin_phi)
                                : 6.0 * sin_phi / (3.0 - sin_phi);

  const auto& first = path.front();
  MaterialPointState start{first.stress, first.void_ratio};
  s.at_rest_ratio = at_rest_stress_ratio(model, mean_pressure(first.stress), first.void_ratio);
  const auto stages = loading_stages(setup, start);
  MixedControlSolver solver(model, stages.front().control);
  const ElementRates r = solver.solve(start);
  switch (setup.kind) {
    case ElementTestKind::isotropic_compression:
      s.initial_stiffness = r.stress_rate.trace() / (3.0 * r.stretching.trace());
      s.stiffness_name = "K = dp/d(eps_v), bulk modulus";
      break;
    case ElementTestKind::oedometric:
    case ElementTestKind::cyclic_oedometric:
      s.initial_stiffness = r.stress_rate(2, 2) / r.stretching(2, 2);
      s.stiffness_name = "M = d(sigma_a)/d(eps_a), constrained modulus";
      break;
    case ElementTestKind::triaxial_compression:
    case ElementTestKind::triaxial_extension:
      s.initial_stiffness = r.stress_rate(2, 2) / r.stretching(2, 2);
      s.stiffness_name = "E = d(sigma_a)/d(eps_a) at constant lateral stress, drained Young's modulus";
      break;
    case ElementTestKind::simple_shear:
      s.initial_stiffness = r.stress_rate(0, 1) / (2.0 * r.stretching(0, 1));
      s.stiffness_name = "G = d(tau)/d(gamma) at constant normal stress, shear modulus";
      break;
  }
  return s;
}

}  // namespace feedflow
