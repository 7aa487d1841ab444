#include "reports/document/report_content.hpp"

#include <algorithm>
#include <set>

#include "models/units/quantity_format.hpp"
#include "reports/margin_table.hpp"
#include "reports/performance_rows.hpp"
#include "reports/result_format.hpp"

namespace feedflow {
namespace {

std::string upper(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return std::toupper(c); });
  return s;
}

bool is_material_key(const std::string& key) { return key.rfind("material.", 0) == 0; }

void add_verdict(ReportContent& c, const DesignRecord& r) {
  c.blocks.push_back(ReportHeading{"Verdict"});
  c.blocks.push_back(
      ReportParagraph{upper(to_string(r.verdict.status)), tone_of(r.verdict.status), true});
  if (const auto margins = margin_table(r.verdict); !margins.empty()) {
    ReportTable t{{"Check", "Requirement", "Achieved (band)", "Margin", "Status"},
                  {},
                  {0.23, 0.16, 0.33, 0.1, 0.18}};
    for (const auto& m : margins)
      t.rows.push_back({m.check, m.requirement, m.achieved, m.margin,
                        std::string(to_string(m.status)) + (m.governing ? " (governs)" : "")});
    c.blocks.push_back(std::move(t));
  }
  c.blocks.push_back(ReportBullets{r.verdict.reasons});
}

void add_results(ReportContent& c, const DesignRecord& r) {
  c.blocks.push_back(ReportHeading{"Results"});
  if (r.results.empty()) {
    c.blocks.push_back(ReportParagraph{"No quantity was computed for this case.", Tone::muted});
    return;
  }
  ReportTable t{{"Quantity", "Value", "Band", "Model", "Rung"}, {}, {2.2, 1.5, 1.7, 3.2, 0.6}};
  for (const auto& [name, e] : r.results)
    t.rows.push_back({quantity_label(name), estimate_value_text(e), estimate_band_text(e), e.model,
                      to_string(e.rung)});
  c.blocks.push_back(std::move(t));
}

// Whether the record is of one case (a design check, a simulation, a sweep): a bench over the
// seed's cases has no equipment, verdict, inputs or material of its own.
bool of_a_case(const DesignRecord& r) { return !r.case_file.empty(); }

void add_inputs(ReportContent& c, const DesignRecord& r) {
  ReportTable t{{"Input", "Value", "Key"}, {}, {2.0, 1.6, 2.4}};
  for (const auto& in : r.inputs)
    if (!is_material_key(in.key)) t.rows.push_back({quantity_label(in.key), in.display, in.key});
  if (t.rows.empty() && !of_a_case(r)) return;
  c.blocks.push_back(ReportHeading{"Inputs"});
  c.blocks.push_back(std::move(t));
}

void add_material_sheet(ReportContent& c, const DesignRecord& r) {
  if (!of_a_case(r) && std::none_of(r.inputs.begin(), r.inputs.end(),
                                    [](const InputValue& in) { return is_material_key(in.key); }))
    return;
  c.blocks.push_back(ReportHeading{"Material data sheet"});
  std::string name, origin;
  ReportTable t{{"Parameter", "Value", "Source"}, {}, {2.3, 1.2, 4.3}};
  for (const auto& in : r.inputs) {
    if (!is_material_key(in.key)) continue;
    if (in.key == "material.name") {
      name = in.display;
      origin = in.source;
      continue;
    }
    t.rows.push_back({in.key.substr(9), in.display, in.source});
  }
  c.blocks.push_back(ReportParagraph{"Material: " + name + (origin.empty() ? "" : " (from " + origin + ")")});
  c.blocks.push_back(std::move(t));
}

void add_provenance(ReportContent& c, const DesignRecord& r, const std::string& generated) {
  c.blocks.push_back(ReportHeading{"Provenance"});
  std::vector<std::string> items;
  items.push_back("feedflow " + r.feedflow_version + ", report generated " + generated);
  if (of_a_case(r)) items.push_back("case file: " + r.case_file);
  if (!r.command_line.empty()) items.push_back("command: " + r.command_line);
  items.push_back("run time: " + format_quantity(r.wall_seconds, r.wall_seconds < 1 ? "ms" : "s", 3));
  std::set<std::string> models;
  for (const auto& [name, e] : r.results) models.insert(e.model + " (" + to_string(e.rung) + ")");
  for (const auto& m : models) items.push_back("model: " + m);
  c.blocks.push_back(ReportBullets{items});
}

}  // namespace

Tone tone_of(VerdictStatus status) {
  switch (status) {
    case VerdictStatus::pass: return Tone::pass;
    case VerdictStatus::marginal: return Tone::marginal;
    case VerdictStatus::fail: return Tone::fail;
    case VerdictStatus::unknown: return Tone::unknown;
  }
  return Tone::unknown;
}

ReportContent design_report_content(const DesignRecord& r, const std::vector<ReportImage>& snapshots,
                                    const std::string& generated) {
  ReportContent c;
  const bool one_case = of_a_case(r);
  c.title = (one_case ? "Design report: " : "Report: ") + r.case_name;
  c.header = "feedflow " + r.feedflow_version + "  |  " + r.case_name +
             (one_case ? " (" + std::string(to_string(r.kind)) + ")" : std::string());
  c.blocks.push_back(ReportHeading{c.title, 0});
  if (!r.description.empty()) c.blocks.push_back(ReportParagraph{r.description});
  c.blocks.push_back(ReportParagraph{(one_case ? std::string("Equipment: ") + to_string(r.kind) +
                                                     ".  Case file: " + r.case_file + ".  "
                                               : std::string()) +
                                         "Generated " + generated + ".",
                                     Tone::muted});

  if (!one_case) {  // no verdict: what it says instead
    if (!r.verdict.reasons.empty()) {
      c.blocks.push_back(ReportHeading{"Notes"});
      c.blocks.push_back(ReportBullets{r.verdict.reasons});
    }
  } else {
    add_verdict(c, r);
  }
  add_results(c, r);

  add_inputs(c, r);

  if (!r.charts.empty()) {
    c.blocks.push_back(ReportHeading{"Figures"});
    for (const auto& chart : r.charts) c.blocks.push_back(ReportChart{chart});
  }
  if (!snapshots.empty()) {
    c.blocks.push_back(ReportHeading{"Pictures"});
    for (const auto& s : snapshots) c.blocks.push_back(s);
  }

  c.blocks.push_back(ReportHeading{"Assumptions and which way each number errs"});
  if (r.assumptions.empty())
    c.blocks.push_back(ReportParagraph{"No model made an assumption beyond the inputs listed.", Tone::muted});
  else
    c.blocks.push_back(ReportBullets{r.assumptions});

  for (const auto& block : r.performance) {
    c.blocks.push_back(ReportHeading{"Performance: " + block.title});
    ReportTable t{
        {"Figure or phase", "Value or time", "Share of the wall time"}, {}, {0.4, 0.4, 0.2}};
    for (const auto& [name, value, share] : performance_rows(block))
      t.rows.push_back({name, value, share});
    c.blocks.push_back(std::move(t));
  }
  add_material_sheet(c, r);
  add_provenance(c, r, generated);
  return c;
}

}  // namespace feedflow
