#include "models/chute/chute_release.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace feedflow {

RampFlowResult run_chute_release(const Chute& chute, const PouliquenLaw& friction,
                                 const ChuteReleaseOptions& options) {
  if (!(chute.length > 0.0 && chute.bin_length > 0.0 && chute.fill_height > 0.0 &&
        chute.gate_opening > 0.0))
    throw std::invalid_argument(
        "chute release needs positive ramp length, bin length, fill height and gate opening");
  if (!(chute.angle > 0.0 && chute.angle < std::numbers::pi / 2))
    throw std::invalid_argument("chute angle must lie in (0, 90) degrees");
  if (!(options.cell_size > 0.0)) throw std::invalid_argument("cell size must be > 0");
  const auto bin_cells = static_cast<std::size_t>(std::lround(chute.bin_length / options.cell_size));
  const auto ramp_cells = static_cast<std::size_t>(std::lround(chute.length / options.cell_size));
  if (bin_cells < 1 || ramp_cells < 2)
    throw std::invalid_argument("cell size too coarse for the bin or the ramp");
  // Uniform cells; the gate face sits at x = 0 exactly.
  const double dx_bin = chute.bin_length / double(bin_cells);
  const double dx_ramp = chute.length / double(ramp_cells);
  const double dx = std::min(dx_bin, dx_ramp);
  const auto nb = static_cast<std::size_t>(std::ceil(chute.bin_length / dx - 1e-9));
  const auto nr = static_cast<std::size_t>(std::ceil(chute.length / dx - 1e-9));
  RampGrid grid{-double(nb) * dx, double(nr) * dx, nb + nr};

  RampPhysics physics;
  physics.angle = chute.angle;
  physics.friction = friction;
  physics.earth_pressure = options.earth_pressure;
  physics.upstream = RampBoundary::Wall;
  physics.downstream = RampBoundary::Outflow;
  physics.gate_face = nb;
  physics.gate_opening = chute.gate_opening;

  std::vector<double> h(grid.cells, 0.0);
  for (std::size_t i = 0; i < nb; ++i) h[i] = chute.fill_height;

  RampFlowSettings settings = options.settings;
  settings.ramp_begin = 0.0;
  settings.probe_position = 0.5 * chute.length;
  return run_ramp_flow(grid, physics, h, {}, settings);
}

}  // namespace feedflow
