#pragma once
// Flow function sigma_c = F(sigma1): unconfined yield strength against major consolidation
// stress (reduced_models.md section 1.1), linear, power law or tabulated; and the bulk density
// at a consolidation stress: constant, from the Bauer compression law, or tabulated. [Pa]
#include <optional>
#include <string>
#include <vector>

#include "models/hopper/tabulated_curve.hpp"
#include "models/material/bulk_compressibility.hpp"

namespace feedflow {

class FlowFunction {
 public:
  enum class Kind { linear, power_law, tabulated };

  // sigma_c = slope sigma1 + intercept [Pa]; slope >= 0.
  static FlowFunction linear(double slope, double intercept);
  // sigma_c = coefficient sigma1^exponent, sigma1 and sigma_c in Pa (coefficient in
  // Pa^(1-exponent)); coefficient >= 0, exponent >= 0.
  static FlowFunction power_law(double coefficient, double exponent);
  // Measured points (sigma1 increasing); piecewise linear, end segments extended beyond them.
  static FlowFunction tabulated(std::vector<double> major_stress,
                                std::vector<double> unconfined_yield_strength);
  // A cohesionless solid: sigma_c = 0 at every stress.
  static FlowFunction cohesionless() { return linear(0.0, 0.0); }

  // sigma_c at sigma1 >= 0, never negative [Pa].
  double unconfined_yield_strength(double major_stress) const;
  Kind kind() const { return kind_; }
  double slope_or_coefficient() const { return a_; }
  double intercept_or_exponent() const { return b_; }
  const std::optional<TabulatedCurve>& table() const { return table_; }
  std::string describe() const;  // "linear: sigma_c = 0.1 sigma1 + 50 Pa"

 private:
  FlowFunction(Kind kind, double a, double b, std::optional<TabulatedCurve> table)
      : kind_(kind), a_(a), b_(b), table_(std::move(table)) {}
  Kind kind_;
  double a_, b_;
  std::optional<TabulatedCurve> table_;
};

class BulkDensity {
 public:
  static BulkDensity constant(double density);
  // rho_b on the critical-state line of the Bauer law at mean pressure
  // p = pressure_per_major_stress * sigma1 (1 takes p = sigma1; the centre of the steady-flow
  // Mohr circle is 1/(1 + sin delta)).
  static BulkDensity compressible(const BulkCompressibility& law,
                                  double pressure_per_major_stress = 1.0);
  // Measured rho_b(sigma1), piecewise linear, end values held beyond the points.
  static BulkDensity tabulated(std::vector<double> major_stress, std::vector<double> density);

  double at(double major_stress) const;  // [kg/m^3]
  std::string describe() const;

 private:
  enum class Kind { constant, compressible, tabulated };
  Kind kind_ = Kind::constant;
  double density_ = 0.0;
  double pressure_per_major_stress_ = 1.0;
  std::optional<BulkCompressibility> law_;
  std::optional<TabulatedCurve> table_;
};

}  // namespace feedflow
