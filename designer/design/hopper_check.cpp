#include "designer/design/hopper_check.hpp"

#include "designer/design/hopper_charts.hpp"
#include "designer/design/judge.hpp"
#include "designer/design/target_units.hpp"
#include "designer/design/verdict_builder.hpp"
#include "models/units/quantity_format.hpp"

namespace feedflow {

HopperModels hopper_models(const ModelChoices& choices, const HopperMaterial& material, const Hopper& h) {
  HopperModels models{&choices.of(flow_factor_models()), &choices.of(critical_outlet_models()),
                      &choices.of(discharge_models())};
  const auto& calibration = material.discharge_calibration;
  if (!choices.is_set(discharge_models().key) && calibration && calibration->geometry == flow_geometry(h) &&
      !calibration->best_row.empty())
    models.discharge = &discharge_models().at(calibration->best_row);
  return models;
}

void check_hopper(const Case& c, const Hopper& h, const ModelChoices& models, DesignDetail detail,
                  DesignRecord& record) {
  HopperMaterial material = HopperMaterial::of(c.material, models.of(hopper_density_models()));
  const HopperModels chosen = hopper_models(models, material, h);
  const HopperAssessment a = assess_hopper(h, std::move(material), chosen);
  HopperEstimates estimates = hopper_estimates(c.material, h, a);
  record.results = std::move(estimates.results);
  VerdictBuilder verdict;
  show_in_target_units(c, record.results);
  for (auto& f : judge_hopper(h, c.design, record.results).findings) verdict.add(std::move(f));
  for (auto& note : estimates.notes) verdict.add(std::move(note));
  record.verdict = verdict.verdict();
  if (detail == DesignDetail::results) return;
  record.charts = hopper_charts(c.material, h, a);
  record.assumptions = hopper_assumptions(c, h, a, !models.is_set(discharge_models().key));
}

std::vector<std::string> hopper_assumptions(const Case& c, const Hopper& h, const HopperAssessment& a,
                                            bool rate_row_from_calibration) {
  const HopperEvaluation& nominal = a.nominal();
  std::vector<std::string> out;
  out.push_back("Critical outlet width: " + nominal.critical_model +
                ". Jenike's method is known to overpredict B_c (errs wide, the safe side); the static-arch "
                "estimate H_a is derived, not a published formula, and falls on steep smooth walls.");
  out.push_back("Bulk density: " + a.material.density_model + ".");
  if (const auto& arching =
          c.material.calibration ? c.material.calibration->arching : std::nullopt) {
    bool calibrated = false;
    arching_strength_scale(a.material, flow_geometry(h), a.models.flow_factor->name,
                           a.models.critical_outlet->name, &calibrated);
    const auto row = arching->rows.find(std::string(a.models.critical_outlet->name));
    if (calibrated) {
      std::string figures;
      for (const auto& [key, words] : {std::pair{"scale_range", "range every bracket allows "},
                                       std::pair{"fit_rms_error", "rms error "},
                                       std::pair{"held_out_max_error", "held-out max error "}})
        if (row->second.figures.count(key))
          figures += std::string("; ") + words + row->second.figures.at(key);
      out.push_back("Arching: the flow function's sigma_c in " +
                    std::string(a.models.critical_outlet->name) +
                    " is scaled by the material's [calibration.arching], fitted to " +
                    arching->rung + " over " + std::to_string(arching->points) +
                    " bracketed critical outlet width(s), commit " + arching->commit + figures +
                    "; valid near the fitted semi-angles and wall friction.");
    } else {
      out.push_back("The material's [calibration.arching] is for " + arching->geometry +
                    " hoppers with hopper.flow_factor=" + arching->flow_factor +
                    (row == arching->rows.end() ? " and other hopper.critical_outlet rows" : "") +
                    ": this check uses the flow function as measured.");
    }
  }
  if (h.is_wedge())
    out.push_back("Wedge: plane flow assumes a slot at least 3 outlet widths long; the mass-flow limit uses the "
                  "interim rule 'conical limit + 8-12 deg' (no verified closed form for plane flow).");
  out.push_back("Continuum arching theory does not model interlocking of particles; the (3-8) d_max rule covers it "
                "roughly.");
  if (a.material.discharge_calibration && a.material.discharge_calibration->geometry == flow_geometry(h)) {
    const auto& fitted = c.material.calibration->discharge;
    const auto row = fitted.find(std::string(nominal.rate_row->name));
    std::string figures;
    if (row != fitted.end())
      for (const char* key : {"fit_rms_error", "held_out_max_error"})
        if (row->second.figures.count(key))
          figures += std::string(figures.empty() ? "" : ", ") + (key == std::string("fit_rms_error") ? "rms error " : "held-out max error ") +
                     row->second.figures.at(key);
    const auto error =
        calibrated_error(*nominal.rate_row, flow_geometry(h), a.material.discharge_calibration);
    const std::string spanned_error =
        error ? "; the rate's band spans the larger, +-" + format_number(*error * 100, 3) + " %"
              : "";
    out.push_back("Discharge: " + nominal.rate_model +
                  " (the material's [calibration]: coefficients fitted to " +
                  c.material.calibration->rung + " over " +
                  std::to_string(c.material.calibration->points) + " design points, commit " +
                  c.material.calibration->commit + (figures.empty() ? "" : "; " + figures) +
                  "; valid within the fitted outlet widths and semi-angles)" + spanned_error + ".");
    const DischargeModel& default_row = discharge_models().default_row();
    if (rate_row_from_calibration && nominal.rate_row != &default_row) {
      const auto fallback = fitted.find(std::string(default_row.name));
      const auto* default_figures = fallback == fitted.end() ? nullptr : &fallback->second.figures;
      const std::string default_error = default_figures && default_figures->count("held_out_max_error")
                                            ? ", held-out max error " + default_figures->at("held_out_max_error")
                                            : "";
      out.push_back("Discharge model: " + std::string(nominal.rate_row->name) +
                    ", the calibrated row that met the full rung best (" +
                    a.material.discharge_calibration->best_row_error + "), in place of the default " +
                    std::string(default_row.name) + " (calibrated too" + default_error +
                    "); --model hopper.discharge=NAME chooses another.");
    }
  } else {
    out.push_back("Discharge: " + nominal.rate_model + "; expect +-20-30 % before calibration; Beverloo tends to "
                  "overpredict for elongated particles.");
    if (a.material.discharge_calibration)
      out.push_back("The material's calibrated discharge coefficients are for " +
                    std::string(c.material.calibration->geometry) + " hoppers: this one uses the published ones.");
  }
  if (!a.material.calibration_note.empty()) out.push_back(a.material.calibration_note + ".");
  if (nominal.drag_factor < 1.0)
    out.push_back("Air drag (Carleton) lowers the rate to " + format_number(nominal.drag_factor * 100, 3) +
                  " % of the drag-free value with d = d50; finer fractions would lower it further.");
  else if (!a.material.particle_density || !a.material.median_size)
    out.push_back("No air-drag correction: it needs the particle density (from [hypoplastic]) and the median size "
                  "(d50 of [psd]), which " + c.material.name + " lacks; fine, light particles discharge slower.");
  for (const auto& [key, source] : c.material.sources)
    if ((key.rfind("flow_properties.", 0) == 0) && source.find("assumed") != std::string::npos) {
      out.push_back("The flow function and effective friction angle of " + c.material.name +
                    " are assumed calibration targets, not measurements: measure the flow function below 1 kPa "
                    "before building (a 0.1 kPa error moves B_c by about 40 mm).");
      break;
    }
  return out;
}

}  // namespace feedflow
