#include "models/hopper/flow_function.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace feedflow {
namespace {

std::string number(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", v);
  return text;
}

}  // namespace

FlowFunction FlowFunction::linear(double slope, double intercept) {
  if (!(slope >= 0.0) || !std::isfinite(slope) || !std::isfinite(intercept))
    throw std::invalid_argument("linear flow function needs a finite slope >= 0");
  return FlowFunction(Kind::linear, slope, intercept, std::nullopt);
}

FlowFunction FlowFunction::power_law(double coefficient, double exponent) {
  if (!(coefficient >= 0.0 && exponent >= 0.0) || !std::isfinite(coefficient) ||
      !std::isfinite(exponent))
    throw std::invalid_argument("power-law flow function needs coefficient >= 0, exponent >= 0");
  return FlowFunction(Kind::power_law, coefficient, exponent, std::nullopt);
}

FlowFunction FlowFunction::tabulated(std::vector<double> sigma1, std::vector<double> sigma_c) {
  if (std::any_of(sigma1.begin(), sigma1.end(), [](double s) { return s < 0.0; }))
    throw std::invalid_argument("flow function table: consolidation stresses must be >= 0");
  return FlowFunction(Kind::tabulated, 0.0, 0.0,
                      TabulatedCurve(std::move(sigma1), std::move(sigma_c),
                                     TabulatedCurve::Beyond::extend_end_segments));
}

double FlowFunction::unconfined_yield_strength(double sigma1) const {
  if (!(sigma1 >= 0.0)) throw std::invalid_argument("consolidation stress must be >= 0");
  double v = 0.0;
  switch (kind_) {
    case Kind::linear: v = a_ * sigma1 + b_; break;
    case Kind::power_law: v = a_ * std::pow(sigma1, b_); break;
    case Kind::tabulated: v = (*table_)(sigma1); break;
  }
  return std::max(v, 0.0);
}

std::string FlowFunction::describe() const {
  switch (kind_) {
    case Kind::linear: return "linear: sigma_c = " + number(a_) + " sigma1 + " + number(b_) + " Pa";
    case Kind::power_law:
      return "power law: sigma_c = " + number(a_) + " sigma1^" + number(b_) + " (Pa)";
    case Kind::tabulated:
      return "tabulated: " + std::to_string(table_->x().size()) + " points, " +
             number(table_->x().front()) + " to " + number(table_->x().back()) + " Pa";
  }
  return {};
}

BulkDensity BulkDensity::constant(double density) {
  if (!(density > 0.0) || !std::isfinite(density))
    throw std::invalid_argument("bulk density must be positive");
  BulkDensity b;
  b.density_ = density;
  return b;
}

BulkDensity BulkDensity::compressible(const BulkCompressibility& law, double ratio) {
  if (!(ratio > 0.0)) throw std::invalid_argument("pressure per major stress must be positive");
  BulkDensity b;
  b.kind_ = Kind::compressible;
  b.law_ = law;
  b.pressure_per_major_stress_ = ratio;
  return b;
}

BulkDensity BulkDensity::tabulated(std::vector<double> sigma1, std::vector<double> density) {
  if (std::any_of(density.begin(), density.end(), [](double r) { return !(r > 0.0); }))
    throw std::invalid_argument("bulk density table: densities must be positive");
  BulkDensity b;
  b.kind_ = Kind::tabulated;
  b.table_.emplace(std::move(sigma1), std::move(density), TabulatedCurve::Beyond::hold_end_values);
  return b;
}

double BulkDensity::at(double sigma1) const {
  if (!(sigma1 >= 0.0)) throw std::invalid_argument("consolidation stress must be >= 0");
  switch (kind_) {
    case Kind::constant: return density_;
    case Kind::compressible: return law_->critical_density(pressure_per_major_stress_ * sigma1);
    case Kind::tabulated: return (*table_)(sigma1);
  }
  return density_;
}

std::string BulkDensity::describe() const {
  switch (kind_) {
    case Kind::constant: return "constant " + number(density_) + " kg/m^3";
    case Kind::compressible: return "Bauer compression law, critical-state line";
    case Kind::tabulated: return "tabulated rho_b(sigma1)";
  }
  return {};
}

}  // namespace feedflow
