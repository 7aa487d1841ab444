#include "reports/text_summary.hpp"

#include <algorithm>
#include <cstdio>
#include <sstream>

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


void row(std::ostringstream& out, const std::string& label, const std::string& value,
         const std::string& note = "") {
  out << "  " << label;
  for (std::size_t i = label.size(); i < 26; ++i) out << ' ';
  out << value;
  if (!note.empty()) out << "   (" << note << ")";
  out << '\n';
}

}  // namespace

std::string text_summary(const DesignRecord& r) {
  std::ostringstream out;
  out << "feedflow " << r.feedflow_version << " design check: " << r.case_name << " ("
      << to_string(r.kind) << ")\n";
  if (!r.description.empty()) out << r.description << '\n';
  out << "case file: " << r.case_file << "\n\n";

  out << "Inputs\n";
  for (const auto& in : r.inputs) {
    // The material's parameters are listed by `feedflow materials NAME`; show its name only.
    if (in.key.rfind("material.", 0) == 0 && in.key != "material.name") continue;
    row(out, quantity_label(in.key == "material.name" ? "material" : in.key), in.display);
  }

  out << "\nResults\n";
  if (r.results.empty()) out << "  none\n";
  if (!r.results.empty()) {
    char line[512];
    std::snprintf(line, sizeof line, "  %-34s %-22s %-26s %-4s %s\n", "quantity", "value", "band", "rung", "model");
    out << line;
    for (const auto& [name, e] : r.results) {
      const std::string band = estimate_band_text(e);
      std::snprintf(line, sizeof line, "  %-34s %-22s %-26s %-4s %s\n", quantity_label(name).c_str(),
                    estimate_value_text(e).c_str(), band.empty() ? "-" : band.c_str(), to_string(e.rung),
                    e.model.c_str());
      out << line;
    }
  }
  out << "\nVerdict: " << upper(to_string(r.verdict.status)) << '\n';
  const auto margins = margin_table(r.verdict);
  if (!margins.empty()) {
    char line[512];
    std::snprintf(line, sizeof line, "  %-30s %-14s %-38s %-10s %s\n", "check", "requirement", "achieved (band)",
                  "margin", "status");
    out << line;
    for (const auto& m : margins) {
      std::snprintf(line, sizeof line, "  %-30s %-14s %-38s %-10s %s%s\n", m.check.c_str(), m.requirement.c_str(),
                    m.achieved.c_str(), m.margin.c_str(), to_string(m.status), m.governing ? " (governs)" : "");
      out << line;
    }
  }
  for (const auto& reason : r.verdict.reasons) out << "  - " << reason << '\n';
  for (const auto& block : r.performance) {
    out << "\nPerformance: " << block.title << '\n';
    char line[256];
    for (const auto& [name, value, share] : performance_rows(block)) {
      if (share.empty())
        std::snprintf(line, sizeof line, "  %-30s %s\n", name.c_str(), value.c_str());
      else
        std::snprintf(line, sizeof line, "  %-30s %-28s %s\n", name.c_str(), value.c_str(),
                      share.c_str());
      out << line;
    }
  }
  out << "\nWall time: "
      << format_quantity(r.wall_seconds, r.wall_seconds < 1.0 ? "ms" : "s", 3) << '\n';
  return out.str();
}

}  // namespace feedflow
