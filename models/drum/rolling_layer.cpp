#include "models/drum/rolling_layer.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

#include "models/core/errors.hpp"
#include "models/drum/drum_regime.hpp"
#include "models/numerics/brent_root.hpp"

namespace feedflow {
namespace {

struct Problem {
  const RollingLayerModel* model;
  double flux, thickness, wall_term;

  double inertial_number(double beta) const {
    const auto& r = model->rheology;
    return 2.5 * flux * r.grain_size /
           (std::sqrt(r.packing * kGravity * std::cos(beta)) * std::pow(thickness, 2.5));
  }
  double residual(double beta) const {
    return std::tan(beta) - friction_coefficient(model->rheology, inertial_number(beta)) -
           wall_term;
  }
};

}  // namespace

RollingLayerState rolling_angle_of_repose(const Drum& drum, const RollingLayerModel& model) {
  check(model.rheology);
  if (!(model.layer_fraction > 0.0 && model.layer_fraction < 1.0))
    throw std::invalid_argument("rolling layer: c_delta must lie in (0, 1)");
  if (!(model.end_wall_friction >= 0.0))
    throw std::invalid_argument("rolling layer: end-wall friction must be >= 0");
  if (!(drum.length > 0.0)) throw std::invalid_argument("drum length must be > 0");
  if (!(drum.speed > 0.0)) throw std::invalid_argument("rolling layer: drum speed must be > 0");
  const auto segment = fill_segment(drum.diameter, drum.fill_fraction);
  Problem p{&model, drum.speed * segment.half_chord * segment.half_chord / 2.0,
            model.layer_fraction * segment.half_chord, 0.0};
  p.wall_term = model.end_wall_friction * p.thickness / drum.length;

  const double lo = std::atan(model.rheology.mu_s);
  const double hi = std::atan(model.rheology.mu_2 + p.wall_term);
  const BrentSearch root =
      brent_search([&p](double beta) { return p.residual(beta); }, lo, hi, {1e-13, 0.0, 200});
  if (!root.converged())
    throw NumericalFailure("rolling layer: Brent root for the angle of repose failed between " +
                           std::to_string(lo) + " and " + std::to_string(hi) +
                           " rad (GSL status " + std::to_string(root.status) +
                           "); check mu_s < mu_2 and the drum speed");
  const double beta = root.root;
  return {beta, p.inertial_number(beta), p.thickness, p.flux};
}

}  // namespace feedflow
