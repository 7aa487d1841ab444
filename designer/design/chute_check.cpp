#include "designer/design/chute_check.hpp"

#include <algorithm>
#include <numbers>

#include "designer/design/judge.hpp"
#include "designer/design/target_units.hpp"
#include "designer/design/verdict_builder.hpp"
#include "models/chute/cohesive_slope.hpp"
#include "models/core/band.hpp"
#include "models/core/errors.hpp"
#include "models/units/angle.hpp"
#include "models/units/quantity_format.hpp"

namespace feedflow {
namespace {

Estimate length_estimate(double value, double low, double high, std::string model, Rung rung) {
  return Estimate{value, "m", low, high, std::move(model), rung, "mm"};
}

// The largest relative error a chute calibration records (0 without one).
double calibration_error(const Material& m) {
  return m.calibration && m.calibration->chute
             ? largest_error(m.calibration->chute->law).value_or(0.0)
             : 0.0;
}

std::string model_text(const Material& m, const StoppingThicknessModel& stop) {
  return std::string(stop.summary) + (m.calibration && m.calibration->chute
                                          ? ", calibrated against " + m.calibration->chute->rung
                                          : std::string());
}

// Rung L0: the stopping thickness over the law's uncertainty and the cohesive infinite slope.
void stopping_results(const Chute& chute, const Material& m, const StoppingThicknessModel& stop, Estimates& results,
                      std::vector<Finding>& notes) {
  const std::string model = model_text(m, stop);
  const StoppingThicknessBand stopping = stopping_thickness_band(m, stop, chute.angle);
  const StoppingThickness& nominal = stopping.nominal;
  results.emplace_back("deposit", labelled(to_string(nominal.outcome), model));
  if (nominal.outcome != DepositOutcome::Deposit) notes.push_back({std::nullopt, "deposit", nominal.words});
  if (stopping.edge) {
    results.emplace_back("deposit_within_uncertainty", labelled(to_string(*stopping.edge), model));
    const std::string at = " at " + format_quantity(chute.angle, "deg", 4) + " (theta1 ";
    const std::string theta1 = format_quantity(stopping.edge_theta1, "deg", 4) + ")";
    notes.push_back({std::nullopt, "deposit_within_uncertainty",
                     *stopping.edge == DepositOutcome::NeverFlowsBelowTheta1
                         ? "within the law's uncertainty the material may never flow" + at +
                               "up to " + theta1 +
                               ": the stopping thickness has no upper bound (the band shown is "
                               "that of the coefficients that leave a layer)"
                         : "within the law's uncertainty the material may flow" + at + "down to " +
                               theta1 + " and leave a layer"});
  }
  if (nominal.outcome == DepositOutcome::NeverFlowsBelowTheta1) return;
  results.emplace_back("stopping_thickness", length_estimate(nominal.thickness, stopping.low,
                                                             stopping.high, model, stop.rung));
  if (m.surface_flow->cohesion > 0.0) {
    // The Mohr-Coulomb infinite slope with the low-stress cohesion, friction tan(theta1).
    const auto slope = cohesive_stopping_depth({m.surface_flow->cohesion, m.surface_flow->theta1, m.bulk.density},
                                               chute.angle);
    if (slope.normal.outcome == DepositOutcome::Deposit)
      results.emplace_back("stopping_thickness_cohesive_slope",
                           length_estimate(slope.normal.thickness, slope.normal.thickness, slope.normal.thickness,
                                           "cohesive Mohr-Coulomb infinite slope (c, phi = theta1)", Rung::L0));
    else
      notes.push_back({std::nullopt, "stopping_thickness_cohesive_slope", "cohesive infinite slope: " + slope.normal.words});
  }
}

// Rung L1: the release from the bin through the gate, run to rest; its band spans L0's.
void deposit_results(const ChuteDeposit& d, const ChuteDepositModel& row, Estimates& results) {
  const RampFlowResult& run = d.run;
  const std::string by = "depth-averaged release from the bin";
  Estimate deposit = length_estimate(run.probe_thickness, run.probe_thickness, run.probe_thickness,
                                     by + " (Savage-Hutter, Pouliquen friction, " +
                                         format_quantity(d.cell_size, "mm", 2) + " cells)",
                                     row.rung);
  // Banded by the stopping thickness's band; below theta1 (no stopping thickness) unbanded.
  const Estimate* stop = find_estimate(results, "stopping_thickness");
  if (stop && stop->low && stop->high) {
    deposit.low = std::min(run.probe_thickness, *stop->low);
    deposit.high = std::max(run.probe_thickness, *stop->high);
  } else {
    deposit.low = deposit.high = std::nullopt;
  }
  results.emplace_back("deposit_thickness_mid_ramp", std::move(deposit));
  results.emplace_back("time_to_rest", unbanded(run.stop_time, "s", by, row.rung));
  const double released = run.initial_volume > 0 ? run.outflow_volume / run.initial_volume : 0.0;
  results.emplace_back("fraction_leaving_ramp", unbanded(released * 100, "%", by, row.rung));
}

std::vector<std::string> chute_assumptions(const Chute& chute, const Material& m,
                                           const StoppingThicknessModel& stop) {
  std::vector<std::string> out{
      "Stopping thickness: " + std::string(stop.summary) +
          " with theta1, theta2 and L from the material" +
          (m.calibration && m.calibration->chute ? " and its chute calibration (below)" : "") +
          "; thicknesses are normal to the ramp.",
      "The L1 release treats the bin as a reservoir feeding the gate (shallow-flow theory "
      "stretched in a bin as deep "
      "as it is long) and a no-slip ramp; its second-order well-balanced scheme on 10 mm cells is "
      "within 2 % of the "
      "refined deposit."};
  if (m.calibration && m.calibration->chute) {
    const ChuteCalibration& c = *m.calibration->chute;
    std::string figures;
    for (const auto& [name, text] : c.law.figures)
      if (name.find("_before") == std::string::npos)
        figures += (figures.empty() ? "" : ", ") + name + " " + text;
    const bool theta1_fitted = c.law.coefficients.contains("theta1");
    const std::string theta1 = "theta1 = " + format_quantity(m.surface_flow->theta1, "deg", 4);
    out.push_back((theta1_fitted ? theta1 + ", " : std::string()) +
                  "theta2 = " + format_quantity(m.surface_flow->theta2, "deg", 4) +
                  " and L = " + format_quantity(m.surface_flow->stop_length, "mm", 4) +
                  " are the material's [calibration.chute], fitted to " + c.rung + " over " +
                  std::to_string(c.points) + " inclinations of " + c.scene + " (commit " +
                  c.commit + ", " + c.date + (figures.empty() ? "" : "; " + figures) + ")" +
                  (theta1_fitted ? std::string() : ", " + theta1 + " held at the material's") +
                  "; the band is widened by " + format_number(100.0 * calibration_error(m), 3) +
                  " %.");
    constexpr double kSlack = 0.5 * kDegree;
    if (chute.angle < c.lowest_angle - kSlack || chute.angle > c.highest_angle + kSlack)
      out.push_back("This chute's " + format_quantity(chute.angle, "deg", 4) +
                    " lies outside the calibrated inclinations (" +
                    format_quantity(c.lowest_angle, "deg", 4) + " to " +
                    format_quantity(c.highest_angle, "deg", 4) +
                    "): the fitted law is extrapolated.");
    return out;
  }
  for (const auto& [key, source] : m.sources)
    if (key.rfind("surface_flow.", 0) == 0 && source.find("assumed") != std::string::npos) {
      out.push_back("theta1, theta2 and L of " + m.name +
                    " are assumed calibration targets, not measurements: measure h_stop at two angles to fit them.");
      break;
    }
  return out;
}

}  // namespace

Material chute_material(const Material& m) {
  if (!m.surface_flow)
    throw InputError(
        m.origin, "material.surface_flow",
        "the chute models need the material's surface-flow law (theta1, theta2, stop_length in "
        "[surface_flow]); material " +
            m.name + " has none");
  if (!m.calibration || !m.calibration->chute) return m;
  Material out = m;
  const CalibratedModel& law = m.calibration->chute->law;
  out.surface_flow->theta2 = law.coefficients.at("theta2");
  out.surface_flow->stop_length = law.coefficients.at("stop_length");
  if (const auto t1 = law.coefficients.find("theta1"); t1 != law.coefficients.end())
    out.surface_flow->theta1 = t1->second;
  if (!(out.surface_flow->theta2 > out.surface_flow->theta1))
    throw InputError(m.origin, "calibration.chute.coefficients.theta2",
                     "expected an angle above theta1 (" +
                         format_quantity(out.surface_flow->theta1, "deg", 4) + "), got " +
                         format_quantity(out.surface_flow->theta2, "deg", 4));
  return out;
}

StoppingThicknessBand stopping_thickness_band(const Material& m, const StoppingThicknessModel& stop,
                                              double angle) {
  StoppingThicknessBand out;
  out.nominal = stop.evaluate(pouliquen_law_of(*m.surface_flow), m, angle);
  Band band;
  band.add(out.nominal.thickness);
  const auto flows = [](DepositOutcome o) { return o != DepositOutcome::NeverFlowsBelowTheta1; };
  for (const auto& corner : corner_laws(*m.surface_flow)) {
    const StoppingThickness at_corner = stop.evaluate(corner, m, angle);
    band.add(at_corner.thickness);
    // The corner furthest from the nominal law's outcome: the highest theta1 that never flows,
    // or the lowest that lets the material flow.
    if (flows(at_corner.outcome) == flows(out.nominal.outcome)) continue;
    const bool further = !out.edge || (flows(at_corner.outcome) ? corner.theta1 < out.edge_theta1
                                                                : corner.theta1 > out.edge_theta1);
    if (further) {
      out.edge = at_corner.outcome;
      out.edge_theta1 = corner.theta1;
    }
  }
  const double error = calibration_error(m);
  band.add(out.nominal.thickness * (1.0 - error));
  band.add(out.nominal.thickness * (1.0 + error));
  out.low = band.low;
  out.high = band.high;
  return out;
}

PouliquenLaw pouliquen_law_of(const SurfaceFlowProperties& s) {
  return {s.theta1, s.theta2, s.stop_length, s.flow_rule_beta, s.flow_rule_gamma};
}

std::vector<PouliquenLaw> corner_laws(const SurfaceFlowProperties& s) {
  std::vector<PouliquenLaw> laws;
  for (double a : {-1.0, 1.0})
    for (double b : {-1.0, 1.0})
      for (double c : {-1.0, 1.0}) {
        PouliquenLaw law = pouliquen_law_of(s);
        law.theta1 = std::max(0.0, s.theta1 + a * s.theta_uncertainty);
        // theta2's upper corner short of 90 deg, where the law has no meaning.
        law.theta2 =
            std::max(law.theta1 + 0.5 * kDegree,
                     std::min(s.theta2 + b * s.theta_uncertainty, 0.5 * (s.theta2 + 90 * kDegree)));
        law.length = s.stop_length * (1.0 + c * s.stop_length_uncertainty);
        laws.push_back(law);
      }
  return laws;
}

void check_chute(const Case& c, const Chute& chute, const ModelChoices& models, DesignDetail detail,
                 DesignRecord& record) {
  const Material m = chute_material(c.material);
  const StoppingThicknessModel& stop = models.of(stopping_thickness_models());
  std::vector<Finding> notes;
  stopping_results(chute, m, stop, record.results, notes);
  // A release from the bin spreads and comes to rest whatever the angle: below theta1 too,
  // where no layer flows steadily (the seed's plane is such a release).
  const ChuteDepositModel& row = models.of(chute_deposit_models());
  const std::optional<ChuteDeposit> deposit =
      row.evaluate(chute, pouliquen_law_of(*m.surface_flow));
  if (deposit) deposit_results(*deposit, row, record.results);
  VerdictBuilder verdict;
  show_in_target_units(c, record.results);
  for (auto& f : judge_chute(chute, c.design, record.results).findings) verdict.add(std::move(f));
  for (auto& note : notes) verdict.add(std::move(note));
  record.verdict = verdict.verdict();
  if (detail == DesignDetail::results) return;
  record.charts = chute_charts(chute, m, stop, deposit);
  record.assumptions = chute_assumptions(chute, m, stop);
}

}  // namespace feedflow
