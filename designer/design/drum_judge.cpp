// The drum's judge (judge.hpp): the regime against the required one, the whole bed
// centrifuging and slip at the shell, from the estimates present.
#include <cmath>
#include <numbers>

#include "designer/design/estimate_reading.hpp"
#include "designer/design/judge.hpp"
#include "designer/design/verdict_builder.hpp"
#include "models/units/angle.hpp"
#include "models/units/quantity_format.hpp"

namespace feedflow {
namespace {

constexpr double kNearBoundary = 1.25;  // a regime within 25 % of a boundary in Fr is marginal

void judge_regime(const Drum& drum, const DesignTargets& t, const Estimates& es, VerdictBuilder& v) {
  const auto got = label_of(es, "regime");
  if (!got) return;
  const Estimate* ratio = number_of(es, "regime_boundary_ratio");
  if (*got == "not measured") {
    v.add(finding(std::nullopt, "regime", "regime not measured: " + find_estimate(es, "regime")->model));
    return;
  }
  const Estimate* fr = number_of(es, "froude_number");
  const std::string text = *got + " at " + format_quantity(drum.speed, "rpm", 3) +
                           (fr ? " (Fr = " + format_number(std::get<double>(fr->value), 3) + ")" : "");
  const std::string& required = t.required_regime;
  const bool near = ratio && std::abs(std::log(std::get<double>(ratio->value))) < std::log(kNearBoundary);
  if (required == "any")
    v.add(finding(std::nullopt, "regime", text, ratio));
  else if (*got != required)
    v.add(finding(VerdictStatus::fail, "regime", required + " required, but the drum runs " + text, ratio));
  else if (near)
    v.add(finding(VerdictStatus::marginal, "regime_boundary_ratio",
                  text + ", within 25 % of a regime boundary in Fr (" + ratio->model +
                      "): PASS needs Fr outside 1/1.25 .. 1.25 x the boundary",
                  ratio, kNearBoundary));
  else
    v.add(finding(VerdictStatus::pass, "regime", text + " as required", ratio));
}

// The whole bed centrifuges from Fr = 1/sqrt(1 - f): said, not judged (the regime is).
void note_full_bed(const Drum& drum, const Estimates& es, VerdictBuilder& v) {
  const Estimate* speed = number_of(es, "full_bed_centrifuging_speed");
  if (!speed || drum.speed < std::get<double>(speed->value) * kRpm) return;
  v.add(finding(std::nullopt, "full_bed_centrifuging_speed",
                "the whole bed centrifuges: " + format_quantity(drum.speed, "rpm", 3) + " is at or above " +
                    shown(*speed),
                speed, drum.speed / kRpm));
}

// No slip at the shell needs tan(wall friction) > (r_g/R) sin(beta_d).
void judge_slip(const Drum& drum, const Estimates& es, VerdictBuilder& v) {
  const Estimate* need = number_of(es, "no_slip_wall_friction");
  if (!need || !drum.wall_friction_angle) return;
  const double mu = std::tan(*drum.wall_friction_angle), value = std::get<double>(need->value);
  const std::string text = "wall friction tan(" + format_quantity(*drum.wall_friction_angle, "deg", 3) + ") = " +
                           format_number(mu, 3) + " against (r_g/R) sin(beta_d) = " + format_number(value, 3);
  if (mu <= value)
    v.add(finding(VerdictStatus::marginal, "no_slip_wall_friction", "the bed may slip at the shell: " + text, need, mu));
  else
    v.add(finding(std::nullopt, "no_slip_wall_friction", "no slip at the shell: " + text, need, mu));
}

}  // namespace

Verdict judge_drum(const Drum& drum, const DesignTargets& t, const Estimates& es) {
  VerdictBuilder v;
  judge_regime(drum, t, es, v);
  note_full_bed(drum, es, v);
  judge_slip(drum, es, v);
  return v.verdict();
}

}  // namespace feedflow
