#pragma once
// A seeded mutator over the shipped case files and materials: each mutant is a case file (and
// sometimes a case-local material file or a broken materials/ entry) plus the command line to
// run it with. The mutations are the ways users and tools get input wrong: another type, another
// unit, a value far out of range, a truncated file, garbage bytes, deep nesting, unknown keys,
// --set overrides, --model choices.
#include <cstdint>
#include <random>
#include <string>
#include <utility>
#include <vector>

namespace feedflow::testing {

struct SourceFile {
  std::string name;  // "pilot_hopper.toml"
  std::string text;
};

struct Mutant {
  std::size_t index = 0;
  std::string base;         // the shipped case it came from
  std::string operation;    // what was done, for the failure message
  std::string case_text;    // written as c.toml in the mutant's folder
  std::vector<std::pair<std::string, std::string>> files;  // more files: relative path -> content
  std::string material_entry;  // "folder", "loop", "dangling": what materials/<name>.toml is instead
  std::vector<std::string> args;  // the command line after the executable
};

class CaseMutator {
 public:
  CaseMutator(std::vector<SourceFile> cases, SourceFile material, std::uint64_t seed)
      : cases_(std::move(cases)), material_(std::move(material)), rng_(seed) {
    for (const auto& c : cases_) collect_keys(c.text, "", keys_);
    collect_keys(material_.text, "material.", keys_);
    for (const char* k : {"dem.slab_depth", "dem.random_seed", "dem.time_step", "dem.end_time",
                          "dem.normal_law", "dem.slab_faces", "dem.cohesion", "dem.force_time_step",
                          "cel.cell_size", "cel.end_time", "design.required_throughput",
                          "design.mass_flow_margin", "design.max_stopping_thickness", "hopper.wall_friction_angle",
                          "material.flow_properties.flow_function", "material.flow_properties.ff_exponent",
                          "material.flow_properties.ff_coefficient", "material.bulk.moisture_content"})
      keys_.emplace_back(k);
  }

  Mutant next(std::size_t index) {
    Mutant m;
    m.index = index;
    const SourceFile& base = cases_[pick(cases_.size())];
    m.base = base.name;
    m.case_text = base.text;
    m.args = {"design", "c.toml", "--out", "o", "-q"};
    const unsigned roll = pick(100);
    if (roll < 25) {
      m.case_text = replace_value(m.case_text, m.operation);
    } else if (roll < 35) {
      m.case_text = scale_value(m.case_text, m.operation);
    } else if (roll < 40) {
      m.case_text = drop_line(m.case_text, m.operation);
    } else if (roll < 45) {
      m.case_text = truncate(m.case_text, m.operation);
    } else if (roll < 50) {
      m.case_text = garbage(m.case_text, m.operation);
    } else if (roll < 54) {
      m.case_text = deep_nesting(m.case_text, m.operation);
    } else if (roll < 58) {
      m.case_text = extra_key(m.case_text, m.operation);
    } else if (roll < 78) {
      overrides(m);
    } else if (roll < 90) {
      std::string op;
      const std::string text = mutate_text(material_.text, op);
      m.files.emplace_back("materials/" + material_.name, text);
      m.operation = "material " + material_.name + ": " + op;
    } else if (roll < 94) {
      broken_material_entry(m);
    } else {
      materials_command(m);
    }
    if (m.args[0] == "design" && base.name.find("hopper") != std::string::npos && pick(5) == 0) {
      static const char* const models[] = {"hopper.discharge=brown", "hopper.discharge=beverloo",
                                           "hopper.flow_factor=rsf", "hopper.critical_outlet=static_arch",
                                           "hopper.bulk_density=constant", "hopper.bulk_density=table"};
      m.args.push_back("--model");
      m.args.push_back(models[pick(std::size(models))]);
      m.operation += " --model " + m.args.back();
    }
    return m;
  }

 private:
  unsigned pick(std::size_t n) { return static_cast<unsigned>(std::uniform_int_distribution<std::size_t>(0, n - 1)(rng_)); }

  // "table.key" of every `key = value` line, prefixed.
  static void collect_keys(const std::string& text, const std::string& prefix, std::vector<std::string>& keys) {
    std::string table;
    std::size_t start = 0;
    while (start < text.size()) {
      const std::size_t end = std::min(text.find('\n', start), text.size());
      const std::string line = text.substr(start, end - start);
      start = end + 1;
      if (line.size() > 2 && line[0] == '[') {
        table = line.substr(1, line.find(']') - 1) + ".";
        continue;
      }
      const auto eq = line.find(" = ");
      if (eq == std::string::npos || line[0] == '#' || line[0] == ' ') continue;
      const std::string key = prefix + table + line.substr(0, eq);
      if (key != "material.name" && key != "material.description") keys.push_back(key);
    }
  }

  // Lines of the form `key = value` (value with any trailing comment).
  static std::vector<std::pair<std::size_t, std::size_t>> value_spans(const std::string& text) {
    std::vector<std::pair<std::size_t, std::size_t>> spans;
    std::size_t start = 0;
    while (start < text.size()) {
      const std::size_t end = std::min(text.find('\n', start), text.size());
      const auto eq = text.find(" = ", start);
      if (eq != std::string::npos && eq < end && text[start] != '#' && text[start] != '[')
        spans.emplace_back(eq + 3, end);
      start = end + 1;
    }
    return spans;
  }

  // A TOML value that is wrong in some way: type, unit, range, size.
  std::string bad_value() {
    static const char* const pool[] = {
        "true", "\"word\"", "[1, 2]", "{ value = 1 }", "{}", "[]", "1979-05-27", "0x1F", "'30 deg'",
        "0", "-1", "1e308", "-1e308", "1e-300", "nan", "inf", "-inf", "-0.0", "1.5", "9223372036854775807",
        "\"1e308 m\"", "\"1e-300 mm\"", "\"-5 deg\"", "\"90 deg\"", "\"89.9 deg\"", "\"0 deg\"", "\"60 deg\"",
        "\"1 mm\"", "\"0.001 mm\"", "\"1e9 m\"", "\"100 %\"", "\"0 %\"", "\"200 %\"", "\"1e400 m\"", "\"30 kg\"",
        "\"3 rpm\"", "\"1e6 rpm\"", "\"10 kPa\"", "\"1e308 Pa\"", "\"0.5 kg/m^3\"", "\"1e6 kg/m^3\"", "\"31 m\"",
        "\"5 mm\"", "\"nan m\"", "\"inf deg\"", "\"1 m m\"", "\"m\"", "\"\"", "\"   \"", "\"1e-320 m\"",
        "\"1.5\"", "\"wedge\"", "\"conical\"", "\"hertz\"", "\"mass\"", "\"tabulated\"", "\"power_law\"",
        "{ value = \"60 mm\", source = 3 }", "{ value = \"60 mm\", sorce = \"x\" }"};
    const unsigned i = pick(std::size(pool) + 2);
    if (i == std::size(pool)) return "\"" + std::string(100000, 'a') + "\"";
    if (i == std::size(pool) + 1) return "\"" + std::string(100000, '7') + " mm\"";
    return pool[i];
  }

  std::string replace_value(const std::string& text, std::string& op) {
    const auto spans = value_spans(text);
    if (spans.empty()) return text;
    const auto [b, e] = spans[pick(spans.size())];
    const std::string value = bad_value();
    op = "value " + text.substr(text.rfind('\n', b) + 1, b - text.rfind('\n', b) - 1) + value.substr(0, 80);
    return text.substr(0, b) + value + text.substr(e);
  }

  std::string scale_value(const std::string& text, std::string& op) {
    static const char* const factors[] = {"0", "-1", "1e-9", "0.001", "0.1", "0.5", "2", "10", "1000", "1e9", "1e300"};
    const auto spans = value_spans(text);
    if (spans.empty()) return text;
    const auto [b, e] = spans[pick(spans.size())];
    const std::string value = text.substr(b, e - b);
    const auto digit = value.find_first_of("0123456789");
    if (digit == std::string::npos) return replace_value(text, op);
    std::size_t used = 0;
    double x = 0.0;
    try {
      x = std::stod(value.substr(digit), &used);
    } catch (...) {
      return replace_value(text, op);
    }
    const std::string factor = factors[pick(std::size(factors))];
    char number[64];
    std::snprintf(number, sizeof number, "%.6g", x * std::stod(factor));
    const std::string scaled = value.substr(0, digit) + number + value.substr(digit + used);
    op = "scale x" + factor + ": " + scaled.substr(0, 80);
    return text.substr(0, b) + scaled + text.substr(e);
  }

  std::string drop_line(const std::string& text, std::string& op) {
    const auto spans = value_spans(text);
    if (spans.empty()) return text;
    const auto [b, e] = spans[pick(spans.size())];
    const std::size_t line = text.rfind('\n', b) + 1;
    op = "drop " + text.substr(line, std::min<std::size_t>(e - line, 60));
    return text.substr(0, line) + text.substr(std::min(e + 1, text.size()));
  }

  std::string truncate(const std::string& text, std::string& op) {
    const std::size_t at = pick(text.size());
    op = "truncate at byte " + std::to_string(at);
    return text.substr(0, at);
  }

  std::string garbage(const std::string& text, std::string& op) {
    std::string g;
    const unsigned n = 1 + pick(16);
    for (unsigned i = 0; i < n; ++i) g += static_cast<char>(pick(256));
    const std::size_t at = pick(text.size() + 1);
    op = "garbage: " + std::to_string(n) + " bytes at " + std::to_string(at);
    return text.substr(0, at) + g + text.substr(at);
  }

  std::string deep_nesting(const std::string& text, std::string& op) {
    static const std::size_t depths[] = {64, 1000, 100000};
    const std::size_t d = depths[pick(std::size(depths))];
    std::string nested;
    switch (pick(4)) {
      case 0: nested = "deep = " + std::string(d, '[') + std::string(d, ']'); break;
      case 1: {
        nested = "deep = ";
        for (std::size_t i = 0; i < d; ++i) nested += "{ a = ";
        nested += "1" + std::string(d, '}');
        break;
      }
      case 2: {
        nested = "a";
        for (std::size_t i = 0; i < d; ++i) nested += ".a";
        nested += " = 1";
        break;
      }
      default: {
        nested = "[hopper";
        for (std::size_t i = 0; i < d; ++i) nested += ".x";
        nested += "]";
      }
    }
    op = "deep nesting, depth " + std::to_string(d) + ": " + nested.substr(0, 40);
    const auto spans = value_spans(text);
    const std::size_t at = spans.empty() ? text.size() : text.rfind('\n', spans[pick(spans.size())].first) + 1;
    return text.substr(0, at) + nested + "\n" + text.substr(at);
  }

  std::string extra_key(const std::string& text, std::string& op) {
    static const char* const extras[] = {"unknown_key = 1", "[extra]", "[hopper]\nshape = \"wedge\"", "[chute]",
                                         "[drum]", "x.y.z = 1", "[case]\nname = \"again\"",
                                         "[case]\nname = \"../../escaped\"", "[design]\nrequired_regime = \"rolling\"",
                                         "[material]\nname = \"own\"", "[material.bulk]\ndensity = \"1 kg/m^3\"",
                                         "[dem]\nrandom_seed = 1.5", "[cel]\ncell_size = \"1 um\""};
    const std::string extra = extras[pick(std::size(extras))];
    op = "extra: " + extra;
    const std::size_t at = pick(2) ? text.size() : text.find('\n') + 1;
    return text.substr(0, at) + extra + "\n" + text.substr(at);
  }

  void overrides(Mutant& m) {
    const unsigned n = 1 + pick(3);
    m.operation = "overrides:";
    for (unsigned i = 0; i < n; ++i) {
      std::string value = bad_value();
      if (value.size() >= 2 && value.front() == '"' && value.back() == '"') value = value.substr(1, value.size() - 2);
      std::string set = keys_[pick(keys_.size())] + "=" + value;
      if (pick(20) == 0) {
        static const char* const malformed[] = {"=", "hopper.=1", "hopper..x=1", "hopper=1", ".x=1", "noequals",
                                                "material=1", "material.bulk=1", "case.name=", "dem.dem.x=1"};
        set = malformed[pick(std::size(malformed))];
      }
      m.args.push_back("--set");
      m.args.push_back(set);
      m.operation += " --set " + set.substr(0, 80);
    }
  }

  std::string mutate_text(const std::string& text, std::string& op) {
    switch (pick(8)) {
      case 0: case 1: case 2: return replace_value(text, op);
      case 3: return scale_value(text, op);
      case 4: return drop_line(text, op);
      case 5: return truncate(text, op);
      case 6: return garbage(text, op);
      default: return extra_key(text, op);
    }
  }

  void broken_material_entry(Mutant& m) {
    static const char* const kinds[] = {"folder", "loop", "dangling", "other_name"};
    const std::string kind = kinds[pick(std::size(kinds))];
    m.operation = "materials/" + material_.name + " is " + kind;
    if (kind == "other_name") {
      std::string text = material_.text;
      const auto at = text.find("name = \"");
      text.replace(at, text.find('"', at + 8) + 1 - at, "name = \"oak\"");
      m.files.emplace_back("materials/" + material_.name, text);
    } else {
      m.material_entry = kind;
    }
  }

  void materials_command(Mutant& m) {
    std::string op;
    m.files.emplace_back("cases/materials/" + material_.name, mutate_text(material_.text, op));
    const std::string name = material_.name.substr(0, material_.name.find('.'));
    m.args = pick(3) ? std::vector<std::string>{"materials", name, "--json", "m.json", "-q"}
                     : std::vector<std::string>{"materials", "--json", "m.json", "-q"};
    m.operation = "materials command, cases/materials/" + material_.name + ": " + op;
  }

  std::vector<SourceFile> cases_;
  SourceFile material_;
  std::vector<std::string> keys_;
  std::mt19937_64 rng_;
};

}  // namespace feedflow::testing
