#include "reports/text_summary.hpp"

#include <algorithm>
#include <sstream>

#include "models/units/quantity_format.hpp"

namespace feedflow {
namespace {

std::string upper(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return std::toupper(c); });
  return s;
}

// "hopper.semi_angle" -> "semi angle"
std::string label_of(const std::string& key) {
  std::string s = key.substr(key.rfind('.') + 1);
  std::replace(s.begin(), s.end(), '_', ' ');
  return s;
}

std::string value_text(const Estimate& e) {
  if (!e.is_number()) return std::get<std::string>(e.value);
  const double v = std::get<double>(e.value);
  std::string s = format_number(v) + (e.unit.empty() ? "" : " " + e.unit);
  if (e.low && e.high)
    s += "  [" + format_number(*e.low) + " .. " + format_number(*e.high) +
         (e.unit.empty() ? "" : " " + e.unit) + "]";
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
    row(out, label_of(in.key == "material.name" ? "material" : in.key), in.display);
  }

  out << "\nResults\n";
  if (r.results.empty()) out << "  none\n";
  for (const auto& [name, e] : r.results)
    row(out, label_of(name), value_text(e), e.model + ", " + to_string(e.rung));

  out << "\nVerdict: " << upper(to_string(r.verdict.status)) << '\n';
  for (const auto& reason : r.verdict.reasons) out << "  - " << reason << '\n';
  out << "\nWall time: "
      << format_quantity(r.wall_seconds, r.wall_seconds < 1.0 ? "ms" : "s", 3) << '\n';
  return out.str();
}

}  // namespace feedflow
