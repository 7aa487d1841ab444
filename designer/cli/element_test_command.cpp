// feedflow element-test <material> --test triaxial --p0 2kPa --e0 0.8 --strain 20%: a laboratory
// element test of the material's hypoplastic law on the CVODE driver, written as a CSV path and
// a JSON summary, so an engineer can see what the eight parameters of the material mean.
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>
#include <numbers>
#include <optional>
#include <sstream>

#include "designer/case/material_library.hpp"
#include "designer/cli/command_options.hpp"
#include "designer/cli/commands.hpp"
#include "designer/cli/output_files.hpp"
#include "designer/cli/output_folder.hpp"
#include "models/core/errors.hpp"
#include "models/hypoplastic/element_tests.hpp"
#include "models/hypoplastic/stress_invariants.hpp"
#include "models/material/bulk_compressibility.hpp"
#include "models/os/atomic_file.hpp"
#include "models/units/quantity_format.hpp"
#include "models/units/quantity_parser.hpp"

namespace feedflow {
namespace {

struct ElementTestArguments {
  std::string material;
  std::string test = "triaxial";
  std::string p0 = "2 kPa";
  std::string e0;  // empty: e_c(p0)
  std::string strain = "20 %";
  std::string variant = "gudehus-bauer";
  int cycles = 3;
  int samples = 200;
  CommandOptions options;
};

double parse_option(const std::string& text, const Dimension& d, const char* option) {
  try {
    return parse_quantity_as(text, d);
  } catch (const UnitError& e) {
    throw InputError(option, "", e.what());
  }
}

std::string known_tests() {
  std::string s;
  for (const auto name : element_test_names()) s += (s.empty() ? "" : ", ") + std::string(name);
  return s;
}

std::string path_csv(std::span<const ElementTestSample> path) {
  std::ostringstream out;
  out << "time [s],stage [-],eps_xx [-],eps_yy [-],eps_zz [-],gamma_xy [-],eps_vol [-],"
         "sigma_xx [Pa],sigma_yy [Pa],sigma_zz [Pa],sigma_xy [Pa],sigma_yz [Pa],sigma_zx [Pa],"
         "p [Pa],q [Pa],q/p [-],phi_mobilised [deg],e [-]\n";
  char line[512];
  for (const auto& s : path) {
    const double p = mean_pressure(s.stress), q = deviatoric_stress(s.stress);
    std::snprintf(line, sizeof line,
                  "%.9g,%d,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,"
                  "%.6g,%.9g\n",
                  s.time, s.stage, s.strain(0, 0), s.strain(1, 1), s.strain(2, 2),
                  2.0 * s.strain(0, 1), s.strain.trace(), s.stress(0, 0), s.stress(1, 1),
                  s.stress(2, 2), s.stress(0, 1), s.stress(1, 2), s.stress(2, 0), p, q,
                  p > 0.0 ? q / p : 0.0, mobilised_friction_angle(s.stress) * 180.0 / std::numbers::pi,
                  s.void_ratio);
    out << line;
  }
  return out.str();
}

nlohmann::ordered_json with_unit(double value, const char* unit) {
  return {{"value", value}, {"unit", unit}};
}

// The checked inputs of one element test: the law, the material's parameters and the start.
struct ElementTestInputs {
  ElementTestKind kind;
  std::string material;
  HypoplasticModel model;
  double p0 = 0.0;
  double e0 = 0.0;
  double strain = 0.0;
};

HypoplasticVariant variant_of(const std::string& name) {
  if (name == "gudehus-bauer") return HypoplasticVariant::gudehus_bauer;
  if (name == "von-wolffersdorff") return HypoplasticVariant::von_wolffersdorff;
  throw InputError("--variant", "", "unknown variant '" + name + "'; known: gudehus-bauer, von-wolffersdorff");
}

ElementTestInputs checked_inputs(const ElementTestArguments& args) {
  const auto kind = element_test_kind(args.test);
  if (!kind)
    throw InputError("--test", "", "unknown element test '" + args.test + "'; known: " + known_tests());
  const HypoplasticVariant variant = variant_of(args.variant);
  ElementTestInputs in{*kind, {}, {}, 0.0, 0.0, 0.0};
  in.p0 = parse_option(args.p0, dim::pressure, "--p0");
  if (!(in.p0 > 0.0)) throw InputError("--p0", "", "the initial mean pressure must be > 0, e.g. 2 kPa");
  in.strain = parse_option(args.strain, dim::dimensionless, "--strain");
  if (!(in.strain > 0.0 && in.strain <= 3.0))
    throw InputError("--strain", "", "the strain must lie in (0, 300 %], e.g. 20 %");
  if (args.cycles < 1) throw InputError("--cycles", "", "need at least one cycle");
  if (args.samples < 2) throw InputError("--samples", "", "need at least two samples per stage");

  const Material material = MaterialLibrary::standard().load(args.material);
  if (!material.hypoplastic)
    throw InputError("", args.material, "material has no [hypoplastic] section; element tests need it");
  in.material = material.name;
  try {
    in.model = make_hypoplastic_model(*material.hypoplastic, variant);
  } catch (const std::invalid_argument& e) {
    throw InputError(material.origin, "hypoplastic", e.what());
  }
  const LimitVoidRatios limits = limit_void_ratios(in.model.parameters, in.p0);
  in.e0 = args.e0.empty() ? limits.e_c : parse_option(args.e0, dim::dimensionless, "--e0");
  if (!(in.e0 >= limits.e_d && in.e0 <= limits.e_i))
    throw InputError("--e0", "", "void ratio " + format_number(in.e0) +
                                     " is outside the admissible range [e_d, e_i] = [" + format_number(limits.e_d) +
                                     ", " + format_number(limits.e_i) + "] at p0 = " + format_quantity(in.p0, "kPa"));
  return in;
}

std::string summary_json(const ElementTestArguments& args, const ElementTestInputs& in, const ElementTestSummary& s) {
  constexpr double deg = 180.0 / std::numbers::pi;
  nlohmann::ordered_json j;
  j["material"] = in.material;
  j["test"] = std::string(element_test_name(in.kind));
  j["variant"] = args.variant;
  j["convention"] = "Cauchy stress, tension positive; p = -tr(sigma)/3; strains are integrals of D";
  j["initial"] = {{"mean_pressure", with_unit(in.p0, "Pa")}, {"void_ratio", with_unit(in.e0, "-")},
                  {"strain", with_unit(in.strain, "-")}};
  j["summary"] = {
      {"peak_friction_angle", with_unit(s.peak_friction_angle * deg, "deg")},
      {"critical_friction_angle", with_unit(in.model.parameters.phi_c * deg, "deg")},
      {"final_stress_ratio", with_unit(s.final_stress_ratio, "-")},
      {"critical_stress_ratio", with_unit(s.critical_stress_ratio, "-")},
      {"final_mean_pressure", with_unit(s.final_mean_pressure, "Pa")},
      {"final_void_ratio", with_unit(s.final_void_ratio, "-")},
      {"critical_void_ratio_at_final_pressure", with_unit(s.critical_void_ratio, "-")},
      {"K0", with_unit(s.at_rest_ratio, "-")},
      {"initial_tangent_stiffness",
       {{"value", s.initial_stiffness}, {"unit", "Pa"}, {"definition", s.stiffness_name}}},
  };
  j["path_csv"] = "element_test.csv";
  return j.dump(2) + "\n";
}

void print_summary(const ElementTestArguments& args, const ElementTestInputs& in, const ElementTestSummary& s,
                   const std::vector<std::filesystem::path>& written) {
  std::cout << "Element test " << element_test_name(in.kind) << " of " << in.material << " (" << args.variant
            << "), from p0 = " << format_quantity(in.p0, "kPa") << ", e0 = " << format_number(in.e0)
            << ", to strain " << format_quantity(in.strain, "%") << "\n"
            << "  peak friction angle       " << format_quantity(s.peak_friction_angle, "deg")
            << " (phi_c " << format_quantity(in.model.parameters.phi_c, "deg") << ")\n"
            << "  final stress ratio q/p    " << format_number(s.final_stress_ratio)
            << " (critical " << format_number(s.critical_stress_ratio) << ")\n"
            << "  final void ratio          " << format_number(s.final_void_ratio)
            << " (e_c " << format_number(s.critical_void_ratio) << " at p = "
            << format_quantity(s.final_mean_pressure, "kPa") << ")\n"
            << "  K0 at the start           " << format_number(s.at_rest_ratio) << "\n"
            << "  start tangent stiffness   " << format_quantity(s.initial_stiffness, "kPa")
            << " (" << s.stiffness_name << ")\n"
            << "Written: ";
  for (std::size_t i = 0; i < written.size(); ++i) std::cout << (i ? ", " : "") << written[i].string();
  std::cout << '\n';
}

int run_element_test_command(const ElementTestArguments& args) {
  const ElementTestInputs in = checked_inputs(args);
  const ElementTestSetup setup{in.kind, in.strain, args.cycles, args.samples};
  const MaterialPointState initial = isotropic_state(in.p0, in.e0);
  const auto path = run_element_test(in.model, initial, loading_stages(setup, initial));
  const ElementTestSummary s = summarize_element_test(in.model, setup, path);

  const std::string test_name(element_test_name(in.kind));
  const auto folder = output_folder(args.options, "element_test_" + test_name, "", false);
  const std::string json = summary_json(args, in, s);
  std::vector<OutputFile> files;
  if (folder) {
    files.push_back({*folder / "element_test.csv", path_csv(path), "--out"});
    files.push_back({*folder / "summary.json", json, "--out"});
  }
  if (!args.options.json.empty() && !args.options.json_to_stdout())
    files.push_back({args.options.json, json, "--json"});
  std::optional<OutputFolder> claimed;
  if (folder) claimed.emplace(*folder, "--out");
  const auto written = write_outputs(files, args.options.json_to_stdout() ? &json : nullptr,
                                     args.options.verbose, claimed ? &*claimed : nullptr);
  if (args.options.human_output()) print_summary(args, in, s, written);
  return 0;
}

}  // namespace

void add_element_test_command(Command& program, int& exit_code) {
  auto args = std::make_shared<ElementTestArguments>();
  auto command = program.subcommand(
      "element-test",
      "run a laboratory element test (triaxial, oedometer, ...) of a material's hypoplastic law");
  command.option("material", args->material, "material name, e.g. loblolly_pine")
      .required()
      .type_name("MATERIAL");
  command.option("--test", args->test, "test: " + known_tests() + " (default triaxial)")
      .type_name("NAME");
  command.option("--p0", args->p0, "initial isotropic mean pressure (default 2 kPa)")
      .type_name("PRESSURE");
  command
      .option("--e0", args->e0, "initial void ratio, within [e_d(p0), e_i(p0)] (default e_c(p0))")
      .type_name("RATIO");
  command
      .option("--strain", args->strain,
              "axial strain (volumetric for isotropic, gamma for simple shear; default 20 %)")
      .type_name("STRAIN");
  command
      .option("--variant", args->variant,
              "rate law: gudehus-bauer (the seed's, default) or von-wolffersdorff")
      .type_name("NAME");
  command.option("--cycles", args->cycles, "cycles of cyclic_oedometric (default 3)");
  command.option("--samples", args->samples, "output points per loading stage (default 200)");
  add_json_option(command, args->options, "the summary JSON");
  command
      .option("--out", args->options.out,
              "output folder (default out/element_test_<test>; none with --json -)")
      .type_name("DIR");
  add_verbosity_options(command, args->options, true);
  command.on_run([args, &exit_code] { exit_code = run_element_test_command(*args); });
}

}  // namespace feedflow
