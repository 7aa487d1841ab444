#include "designer/calibrate/arching_fit.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "models/numerics/brent_root.hpp"
#include "models/numerics/least_squares.hpp"

namespace feedflow {
namespace {

// The factors on sigma_c searched: a flow function a hundredth to a hundred times as strong.
constexpr double kLowestScale = 0.01, kHighestScale = 100.0;

// The row's B_c [m] at the observation with sigma_c times `scale`, as the design check
// evaluates it at the nominal material values.
double row_width(const CriticalOutletModel& row, double scale, const Hopper& h, HopperMaterial& m,
                 const HopperModels& models) {
  m.arching_calibration->strength_scale[std::string(row.name)] = scale;
  HopperModels chosen = models;
  chosen.critical_outlet = &row;
  const auto variant = material_variants(m, *h.wall_friction_angle).front();
  return evaluate_hopper(h, h.semi_angle, h.outlet_width, m, variant, chosen).critical_width;
}

// log(B_c / reference), bounded: a flow function too weak to arch (B_c 0) lies far below any
// reference, one that never meets the flow factor's line (no finite B_c) far above.
double log_ratio(double width, double reference) {
  constexpr double kFar = 50.0;
  if (!(width > 0.0)) return -kFar;
  if (!std::isfinite(width)) return kFar;
  return std::clamp(std::log(width / reference), -kFar, kFar);
}

// The scale at which the row's B_c is `width` at the observation (B_c grows with the scale);
// the end of the searched range where it stays below or above it.
double scale_for_width(const CriticalOutletModel& row, double width, const Hopper& h,
                       HopperMaterial& m, const HopperModels& models) {
  const auto gap = [&](double log_scale) {
    return log_ratio(row_width(row, std::exp(log_scale), h, m, models), width);
  };
  const double lo = std::log(kLowestScale), hi = std::log(kHighestScale);
  if (gap(lo) >= 0.0) return kLowestScale;
  if (gap(hi) <= 0.0) return kHighestScale;
  return std::exp(
      brent_root(gap, lo, hi, 1e-9, 0.0, "arching calibration: the strength scale for B_c"));
}

}  // namespace

double ArchingObservation::reference() const { return std::sqrt(arches_at * flows_at); }

std::vector<ArchingRowFit> fit_arching(const std::vector<ArchingObservation>& obs, HopperMaterial m,
                                       const HopperModels& models) {
  std::vector<std::size_t> fitted;
  for (std::size_t i = 0; i < obs.size(); ++i) {
    if (!(obs[i].arches_at > 0.0 && obs[i].arches_at < obs[i].flows_at))
      throw std::invalid_argument("arching calibration: a bracket must arch below where it flows");
    if (flow_geometry(obs[i].hopper) != flow_geometry(obs.front().hopper))
      throw std::invalid_argument(
          "arching calibration: the points must be hoppers of one geometry");
    if (!obs[i].held_out) fitted.push_back(i);
  }
  if (fitted.empty()) throw std::invalid_argument("arching calibration: no fitted point");
  m.arching_calibration = ArchingScale{
      flow_geometry(obs.front().hopper), std::string(models.flow_factor->name), {}, ""};

  std::vector<ArchingRowFit> out;
  for (const CriticalOutletModel& row : critical_outlet_models().rows) {
    ArchingRowFit f;
    f.row = &row;
    const auto residuals = [&](std::span<const double> p, std::span<double> r) {
      for (std::size_t k = 0; k < fitted.size(); ++k) {
        const ArchingObservation& o = obs[fitted[k]];
        r[k] = log_ratio(row_width(row, std::exp(p[0]), o.hopper, m, models), o.reference());
      }
    };
    f.scale = std::exp(least_squares(residuals, {0.0}, fitted.size()).parameters[0]);
    f.scale_low = kLowestScale;
    f.scale_high = kHighestScale;
    for (std::size_t i : fitted) {
      f.scale_low =
          std::max(f.scale_low, scale_for_width(row, obs[i].arches_at, obs[i].hopper, m, models));
      f.scale_high =
          std::min(f.scale_high, scale_for_width(row, obs[i].flows_at, obs[i].hopper, m, models));
    }
    double fit_before = 0.0, fit_after = 0.0;
    for (std::size_t i = 0; i < obs.size(); ++i) {
      const ArchingObservation& o = obs[i];
      f.width_before.push_back(row_width(row, 1.0, o.hopper, m, models));
      f.width_after.push_back(row_width(row, f.scale, o.hopper, m, models));
      const auto holds = [&](double w) { return w >= o.arches_at && w <= o.flows_at; };
      f.held_before += holds(f.width_before.back());
      f.held_after += holds(f.width_after.back());
      // An error the size of the root search's tolerance is none.
      const auto error = [&](double w) {
        const double e = relative_error(w, o.reference());
        return e < 1e-8 ? 0.0 : e;
      };
      const double before = error(f.width_before.back()), after = error(f.width_after.back());
      if (o.held_out) {
        f.held_out_max_before = std::max(f.held_out_max_before, before);
        f.held_out_max_after = std::max(f.held_out_max_after, after);
      } else {
        fit_before += before * before;
        fit_after += after * after;
      }
    }
    f.fit_rms_before = std::sqrt(fit_before / static_cast<double>(fitted.size()));
    f.fit_rms_after = std::sqrt(fit_after / static_cast<double>(fitted.size()));
    out.push_back(std::move(f));
  }
  return out;
}

}  // namespace feedflow
