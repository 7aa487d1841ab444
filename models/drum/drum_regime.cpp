#include "models/drum/drum_regime.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>

#include "models/chute/pouliquen_law.hpp"
#include "models/core/errors.hpp"
#include "models/numerics/brent_root.hpp"

namespace feedflow {
namespace {

void check_drum(double diameter, double speed) {
  if (!(diameter > 0.0)) throw std::invalid_argument("drum diameter must be > 0");
  if (!(speed >= 0.0)) throw std::invalid_argument("drum speed must be >= 0");
}

}  // namespace

double drum_froude(double diameter, double speed) {
  check_drum(diameter, speed);
  return speed * speed * diameter / (2.0 * kGravity);
}

double drum_critical_speed(double diameter) {
  check_drum(diameter, 0.0);
  return std::sqrt(2.0 * kGravity / diameter);
}

FillSegment fill_segment(double diameter, double f) {
  check_drum(diameter, 0.0);
  if (!(f > 0.0 && f < 1.0)) throw std::invalid_argument("drum fill fraction must lie in (0, 1)");
  const auto fill_mismatch = [f](double eps) {
    return (2.0 * eps - std::sin(2.0 * eps)) / (2.0 * std::numbers::pi) - f;
  };
  const BrentSearch root = brent_search(fill_mismatch, 0.0, std::numbers::pi, {1e-14, 0.0, 200});
  if (!root.converged())
    throw NumericalFailure("drum fill segment: Brent root for the chord half-angle did not "
                           "converge at f = " + std::to_string(f));
  const double eps = root.root;
  const double R = diameter / 2.0, s3 = std::pow(std::sin(eps), 3);
  return {eps, R * std::sin(eps), 4.0 * R * s3 / (3.0 * (2.0 * eps - std::sin(2.0 * eps)))};
}

const char* to_string(DrumRegime regime) {
  switch (regime) {
    case DrumRegime::Slumping: return "slumping";
    case DrumRegime::Rolling: return "rolling";
    case DrumRegime::Cascading: return "cascading";
    case DrumRegime::Cataracting: return "cataracting";
    case DrumRegime::Centrifuging: return "centrifuging";
  }
  return "?";
}

std::array<RegimeBoundary, 4> regime_boundaries(const DrumRegimeThresholds& t) {
  return {{{"slumping | rolling", t.slumping_to_rolling},
           {"rolling | cascading", t.rolling_to_cascading},
           {"cascading | cataracting", t.cascading_to_cataracting},
           {"centrifuging (outer layer)", t.centrifuging}}};
}

DrumRegimeAssessment assess_drum_regime(const Drum& drum, const DrumRegimeThresholds& t,
                                        std::optional<double> angle_of_repose) {
  if (!(0.0 < t.slumping_to_rolling && t.slumping_to_rolling < t.rolling_to_cascading &&
        t.rolling_to_cascading < t.cascading_to_cataracting &&
        t.cascading_to_cataracting < t.centrifuging))
    throw std::invalid_argument("drum regime thresholds must be positive and rise");
  const auto segment = fill_segment(drum.diameter, drum.fill_fraction);
  DrumRegimeAssessment a;
  a.froude = drum_froude(drum.diameter, drum.speed);
  a.critical_speed = drum_critical_speed(drum.diameter);
  if (a.froude < t.slumping_to_rolling) a.regime = DrumRegime::Slumping;
  else if (a.froude < t.rolling_to_cascading) a.regime = DrumRegime::Rolling;
  else if (a.froude < t.cascading_to_cataracting) a.regime = DrumRegime::Cascading;
  else if (a.froude < t.centrifuging) a.regime = DrumRegime::Cataracting;
  else a.regime = DrumRegime::Centrifuging;
  a.full_bed_centrifuging_froude = 1.0 / std::sqrt(1.0 - drum.fill_fraction);
  a.full_bed_centrifuges = a.froude >= a.full_bed_centrifuging_froude;
  a.words = std::string(to_string(a.regime)) + " at Fr = " + std::to_string(a.froude);
  if (a.regime == DrumRegime::Centrifuging)
    a.words += a.full_bed_centrifuges ? "; the whole bed centrifuges"
                                      : "; the outer layer centrifuges, the inner bed does not";
  if (angle_of_repose) {
    a.no_slip_friction = segment.centroid_radius / (drum.diameter / 2.0) * std::sin(*angle_of_repose);
    if (drum.wall_friction_angle) {
      a.wall_slips = std::tan(*drum.wall_friction_angle) <= a.no_slip_friction;
      a.words += *a.wall_slips ? "; the bed slips on the shell" : "; no slip at the shell";
    }
  }
  return a;
}

}  // namespace feedflow
