#include "models/hopper/bin_stresses.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

namespace feedflow {
namespace {

void check(const JanssenBin& b) {
  if (!(b.hydraulic_radius > 0.0 && b.bulk_density > 0.0 && b.stress_ratio > 0.0 &&
        b.wall_friction > 0.0 && b.gravity > 0.0 && b.surcharge >= 0.0))
    throw std::invalid_argument("Janssen bin needs positive A/U, density, lambda, mu_w and g");
}

double decay_length(const JanssenBin& b) {
  return b.hydraulic_radius / (b.stress_ratio * b.wall_friction);
}

}  // namespace

const char* to_string(StressRatioRule rule) {
  switch (rule) {
    case StressRatioRule::jaky: return "Jaky, 1 - sin phi";
    case StressRatioRule::en1991_4: return "EN 1991-4, 1.1 (1 - sin phi_i)";
    case StressRatioRule::schulze: return "Schulze flow design, 1.2 (1 - sin phi_e)";
    case StressRatioRule::rankine_active: return "Rankine active, (1 - sin phi)/(1 + sin phi)";
  }
  return "";
}

double janssen_stress_ratio(StressRatioRule rule, double phi) {
  if (!(phi > 0.0 && phi < 0.5 * std::numbers::pi))
    throw std::invalid_argument("friction angle must lie in (0, 90) deg");
  const double s = std::sin(phi);
  switch (rule) {
    case StressRatioRule::jaky: return 1.0 - s;
    case StressRatioRule::en1991_4: return 1.1 * (1.0 - s);
    case StressRatioRule::schulze: return 1.2 * (1.0 - s);
    case StressRatioRule::rankine_active: return (1.0 - s) / (1.0 + s);
  }
  return 1.0 - s;
}

double plane_bin_hydraulic_radius(double width, std::optional<double> length) {
  if (!(width > 0.0) || (length && !(*length > 0.0)))
    throw std::invalid_argument("bin width and length must be positive");
  if (!length) return 0.5 * width;
  return width * *length / (2.0 * (width + *length));
}

double round_bin_hydraulic_radius(double diameter) {
  if (!(diameter > 0.0)) throw std::invalid_argument("bin diameter must be positive");
  return 0.25 * diameter;
}

double janssen_asymptotic_stress(const JanssenBin& b) {
  check(b);
  return b.bulk_density * b.gravity * decay_length(b);
}

double janssen_depth_to_fraction(const JanssenBin& b, double fraction) {
  check(b);
  if (!(fraction > 0.0 && fraction < 1.0))
    throw std::invalid_argument("fraction of the asymptotic stress must lie in (0, 1)");
  return -decay_length(b) * std::log(1.0 - fraction);
}

BinStressPoint janssen_stress(const JanssenBin& b, double z) {
  check(b);
  if (!(z >= 0.0)) throw std::invalid_argument("depth must be >= 0");
  const double decay = std::exp(-z / decay_length(b));
  const double sv = janssen_asymptotic_stress(b) * (1.0 - decay) + b.surcharge * decay;
  const double sn = b.stress_ratio * sv;
  return {z, sv, sn, b.wall_friction * sn};
}

std::vector<BinStressPoint> janssen_profile(const JanssenBin& b, double depth, int points) {
  if (points < 2) throw std::invalid_argument("a stress profile needs at least 2 points");
  if (!(depth > 0.0)) throw std::invalid_argument("bin depth must be positive");
  std::vector<BinStressPoint> profile;
  profile.reserve(static_cast<std::size_t>(points));
  for (int i = 0; i < points; ++i) profile.push_back(janssen_stress(b, depth * i / (points - 1)));
  return profile;
}

}  // namespace feedflow
