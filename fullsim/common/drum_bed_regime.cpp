#include "fullsim/common/drum_bed_regime.hpp"

#include <algorithm>
#include <cstdio>

#include "models/units/angle.hpp"

namespace feedflow {

const char* to_string(DrumBedRegime regime) {
  switch (regime) {
    case DrumBedRegime::slipping: return "slipping";
    case DrumBedRegime::slumping: return "slumping";
    case DrumBedRegime::rolling: return "rolling";
    case DrumBedRegime::cascading: return "cascading";
    case DrumBedRegime::cataracting: return "cataracting";
    case DrumBedRegime::centrifuging: return "centrifuging";
  }
  return "rolling";
}

namespace {

std::string text(const char* format, double a, double b) {
  char buffer[200];
  std::snprintf(buffer, sizeof buffer, format, a, b);
  return buffer;
}

}  // namespace

DrumRegimeCall classify_drum_bed(const DrumBedState& s, const DrumRegimeCriteria& c) {
  if (s.solid_body_fraction >= c.centrifuging_solid_body &&
      s.over_top_fraction >= c.centrifuging_over_top)
    return {DrumBedRegime::centrifuging,
            text("%.0f %% of the bed turns with the shell and %.0f %% is over the top of the drum",
                 100 * s.solid_body_fraction, 100 * s.over_top_fraction)};
  if (s.airborne_fraction >= c.cataracting_airborne)
    return {DrumBedRegime::cataracting,
            text("%.1f %% of the bed flies above it (threshold %.1f %%)", 100 * s.airborne_fraction,
                 100 * c.cataracting_airborne)};
  if (s.shell_speed_ratio < c.slipping_shell_speed)
    return {DrumBedRegime::slipping, text("the layer at the shell moves at %.2f of the shell speed "
                                          "(threshold %.2f)",
                                          s.shell_speed_ratio, c.slipping_shell_speed)};
  if (s.solid_body_fraction >= c.slumping_solid_body && s.angle_swing >= c.slumping_swing)
    return {DrumBedRegime::slumping,
            text("%.0f %% of the bed turns with the shell between avalanches; the "
                 "surface angle swings by %.1f deg",
                 100 * s.solid_body_fraction, in_degrees(s.angle_swing))};
  const double one_particle = s.particles > 0.0 ? 1.0 / s.particles : 0.0;
  const double cascading_airborne = std::max(c.cascading_airborne, one_particle);
  if (s.airborne_fraction >= cascading_airborne)
    return {DrumBedRegime::cascading,
            text("%.2f %% of the bed leaves the surface in flight (threshold "
                 "%.2f %%)",
                 100 * s.airborne_fraction, 100 * cascading_airborne)};
  if (s.surface_bulge >= c.cascading_bulge)
    return {DrumBedRegime::cascading,
            text("the surface bends by %.1f %% of R from its line (threshold "
                 "%.1f %%)",
                 100 * s.surface_bulge, 100 * c.cascading_bulge)};
  return {DrumBedRegime::rolling, text("continuous surface flow: %.3f %% of the bed in flight, the "
                                       "surface bends by %.1f %% of R",
                                       100 * s.airborne_fraction, 100 * s.surface_bulge)};
}

}  // namespace feedflow
