#include "models/hopper/critical_outlet.hpp"

#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <vector>

#include "models/numerics/brent_root.hpp"

namespace feedflow {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

std::string format(const char* pattern, double a, double b = 0.0, double c = 0.0) {
  char text[256];
  std::snprintf(text, sizeof text, pattern, a, b, c);
  return text;
}

CriticalPoint no_arch() { return {ArchingOutcome::no_cohesive_arch, 0.0, 0.0, false}; }
CriticalPoint no_outlet() { return {ArchingOutcome::no_gravity_outlet, 0.0, 0.0, false}; }
CriticalPoint at(double sigma1, double ff) {
  return {ArchingOutcome::critical_width, sigma1, sigma1 / ff, false};
}

CriticalPoint linear_point(double a, double b, double ff) {
  const double k = 1.0 / ff - a;  // g(sigma1) = b - k sigma1
  if (b > 0.0) return k > 0.0 ? at(b / k, ff) : no_outlet();
  return k < 0.0 ? no_outlet() : no_arch();  // b <= 0: only a slope above 1/ff arches
}

CriticalPoint power_point(double a, double b, double ff) {
  if (a == 0.0) return no_arch();
  if (b < 1.0) return at(std::pow(a * ff, 1.0 / (1.0 - b)), ff);
  if (b == 1.0) return a > 1.0 / ff ? no_outlet() : no_arch();
  return no_outlet();  // b > 1: the flow function overtakes the ff line at high stress
}

// Tabulated: sample g = F - sigma1/ff at 0+, the table points and far beyond (where the end
// segment decides its sign), then solve the last + to - change with Brent.
CriticalPoint table_point(const FlowFunction& f, double ff) {
  const auto g = [&](double s) { return f.unconfined_yield_strength(s) - s / ff; };
  const auto& xs = f.table()->x();
  std::vector<double> at_x{1e-9};
  for (double x : xs)
    if (x > at_x.back()) at_x.push_back(x);
  double far = 2.0 * xs.back() + 1.0;
  const int end_sign = [&] {
    const double slope =
        (f.table()->y().back() - f.table()->y()[xs.size() - 2]) / (xs.back() - xs[xs.size() - 2]);
    if (slope > 1.0 / ff) return 1;
    if (slope < 1.0 / ff) return -1;
    return g(xs.back()) > 0.0 ? 1 : -1;
  }();
  while ((g(far) > 0.0 ? 1 : -1) != end_sign && far < 1e15) far *= 2.0;
  at_x.push_back(far);
  bool any_positive = false, any_negative = false;
  std::size_t last_change = 0;
  for (std::size_t i = 0; i < at_x.size(); ++i) {
    const bool positive = g(at_x[i]) > 0.0;
    (positive ? any_positive : any_negative) = true;
    if (i > 0 && positive != (g(at_x[i - 1]) > 0.0) && !positive) last_change = i;
  }
  if (!any_positive) return no_arch();
  if (!any_negative || end_sign > 0) return no_outlet();
  const double s = brent_root(g, at_x[last_change - 1], at_x[last_change], 1e-12, 1e-12,
                              "critical point of the tabulated flow function");
  CriticalPoint p = at(s, ff);
  p.extrapolated = !f.table()->covers(s);
  return p;
}

CriticalOutlet outlet_from(const CriticalPoint& p, double arch_factor, const BulkDensity& density,
                           double gravity, std::string model) {
  CriticalOutlet o{p.outcome,      0.0,
                   arch_factor,    p.major_stress,
                   p.strength,     density.at(p.major_stress),
                   p.extrapolated, std::move(model)};
  if (p.outcome == ArchingOutcome::critical_width)
    o.width = arching_width(arch_factor, p.strength, o.bulk_density, gravity);
  else if (p.outcome == ArchingOutcome::no_gravity_outlet)
    o.width = kInfinity;
  return o;
}

void require_flow_factor(double ff) {
  if (!(ff > 0.0) || !std::isfinite(ff)) throw std::invalid_argument("flow factor must be > 0");
}

}  // namespace

std::string CriticalOutlet::statement() const {
  switch (outcome) {
    case ArchingOutcome::critical_width:
      return format("arches below %.1f mm (sigma_c,crit %.3g Pa at sigma1 %.3g Pa)", width * 1e3,
                    critical_strength, major_stress) +
             (extrapolated ? "; the flow function was extrapolated beyond its table" : "");
    case ArchingOutcome::no_cohesive_arch:
      return "no cohesive arch (B_c = 0): the flow function lies below the flow-factor line at "
             "every stress; mechanical arching is not excluded";
    case ArchingOutcome::no_gravity_outlet:
      return "no gravity outlet prevents arching: the flow function lies above the flow-factor "
             "line at high stress; flow aids are needed";
  }
  return {};
}

const char* arching_label(ArchingOutcome o) {
  switch (o) {
    case ArchingOutcome::critical_width: return "cohesive arch below B_c";
    case ArchingOutcome::no_cohesive_arch: return "no cohesive arch";
    case ArchingOutcome::no_gravity_outlet: return "no gravity outlet";
  }
  return "";
}

const char* to_string(ArchingOutcome o) {
  switch (o) {
    case ArchingOutcome::critical_width: return "critical width";
    case ArchingOutcome::no_cohesive_arch: return "no cohesive arch";
    case ArchingOutcome::no_gravity_outlet: return "no gravity outlet prevents arching";
  }
  return "";
}

CriticalPoint critical_point(const FlowFunction& f, double ff) {
  require_flow_factor(ff);
  switch (f.kind()) {
    case FlowFunction::Kind::linear:
      return linear_point(f.slope_or_coefficient(), f.intercept_or_exponent(), ff);
    case FlowFunction::Kind::power_law:
      return power_point(f.slope_or_coefficient(), f.intercept_or_exponent(), ff);
    case FlowFunction::Kind::tabulated: return table_point(f, ff);
  }
  return no_arch();
}

double arching_width(double arch_factor, double strength, double rho, double gravity) {
  if (!(rho > 0.0 && gravity > 0.0 && arch_factor > 0.0 && strength >= 0.0))
    throw std::invalid_argument("arching width needs positive density, g, arch factor");
  return arch_factor * strength / (rho * gravity);
}

CriticalOutlet jenike_critical_outlet(FlowGeometry g, double theta, double ff,
                                      const FlowFunction& f, const BulkDensity& density,
                                      double gravity) {
  return outlet_from(critical_point(f, ff), jenike_arch_factor(g, theta), density, gravity,
                     std::string("Jenike critical outlet, H = ") +
                         (g == FlowGeometry::plane ? "1 + theta/180" : "2 + theta/60"));
}

double static_arch_factor(double theta, double phi_w) {
  if (!(theta > 0.0 && theta < 0.5 * std::numbers::pi))
    throw std::invalid_argument("hopper semi-angle must lie in (0, 90) deg");
  if (!(phi_w >= 0.0 && phi_w < 0.5 * std::numbers::pi))
    throw std::invalid_argument("wall friction angle must lie in [0, 90) deg");
  const double tw = theta + phi_w;
  return 2.0 * std::cos(phi_w) * std::pow(std::sin(tw), 3) /
         (tw * std::sin(theta) + std::sin(tw) * std::sin(phi_w));
}

CriticalOutlet static_arch_critical_outlet(double theta, double phi_w, double ff,
                                           const FlowFunction& f, const BulkDensity& density,
                                           double gravity) {
  return outlet_from(critical_point(f, ff), static_arch_factor(theta, phi_w), density, gravity,
                     "static arch, wall-friction limited (Walker/Enstad type, plane)");
}

MechanicalArching mechanical_arching_width(double d_max, double low, double high) {
  if (!(d_max > 0.0 && low > 0.0 && high >= low))
    throw std::invalid_argument("mechanical arching needs d_max > 0 and 0 < low <= high");
  return {low * d_max, high * d_max,
          format("mechanical (interlocking) arching, B ~ %g-%g d_max", low, high)};
}

double minimum_slot_length(double outlet_width) {
  if (!(outlet_width > 0.0)) throw std::invalid_argument("outlet width must be positive");
  return 3.0 * outlet_width;
}

bool slot_length_sufficient(double slot_length, double outlet_width) {
  return slot_length >= minimum_slot_length(outlet_width);
}

}  // namespace feedflow
