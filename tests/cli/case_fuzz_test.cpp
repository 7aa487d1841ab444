// A seeded fuzz of the real executable: mutants of the shipped cases and materials (types,
// units, ranges, truncation, garbage bytes, deep nesting, --set overrides, broken material
// entries) through `feedflow design` and `feedflow materials`. Every run must end in a result or
// a named error: no crash, no hang, no internal error, an exit code of 0, 2, 3 or 4, an exit 2
// that names the file or the option, no non-finite number in a written result, and nothing
// written on an error exit. FEEDFLOW_FUZZ_SEED and FEEDFLOW_FUZZ_MUTANTS change the seed and
// the count (the default run is what CI runs); a failure prints the seed and the mutant.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <map>
#include <nlohmann/json.hpp>
#include <regex>
#include <sstream>
#include <thread>

#include "case_mutator.hpp"
#include "child_process.hpp"

namespace fs = std::filesystem;
using namespace feedflow::testing;

namespace {

constexpr std::uint64_t kSeed = 20260521;
constexpr std::size_t kMutants = 520;

std::uint64_t env_number(const char* name, std::uint64_t fallback) {
  const char* v = std::getenv(name);
  return v && *v ? std::strtoull(v, nullptr, 10) : fallback;
}

void write_mutant(const fs::path& folder, const Mutant& m) {
  fs::create_directories(folder / "materials");
  std::ofstream(folder / "c.toml", std::ios::binary) << m.case_text;
  for (const auto& [path, text] : m.files) {
    fs::create_directories((folder / path).parent_path());
    std::ofstream(folder / path, std::ios::binary) << text;
  }
  const fs::path entry = folder / "materials/loblolly_pine.toml";
  if (m.material_entry == "folder") fs::create_directories(entry);
  if (m.material_entry == "loop") {
    fs::create_symlink("loop.toml", entry);
    fs::create_symlink("loblolly_pine.toml", folder / "materials/loop.toml");
  }
  if (m.material_entry == "dangling") fs::create_symlink("nowhere.toml", entry);
}

// Numbers that JSON cannot hold (NaN, inf) are written as null: a null where a number belongs.
std::string non_finite_in_results(const nlohmann::json& j) {
  for (const auto& [key, e] : j.at("results").items()) {
    if (e.contains("value") && e.at("value").is_null()) return "results." + key + ".value is null";
    const bool low = e.contains("low") && !e.at("low").is_null();
    const bool high = e.contains("high") && !e.at("high").is_null();
    if (low != high) return "results." + key + " has one band edge null";
  }
  for (const auto& chart : j.at("charts"))
    for (const auto& series : chart.at("series"))
      for (const char* axis : {"x", "y", "y_upper"})
        if (series.contains(axis))
          for (const auto& v : series.at(axis))
            if (!v.is_number()) return "chart " + chart.at("id").get<std::string>() + " has a null point";
  std::string found;
  std::function<void(const nlohmann::json&, const std::string&)> walk = [&](const nlohmann::json& n,
                                                                             const std::string& at) {
    if (n.is_null() && found.empty()) found = "inputs" + at + " is null";
    if (n.is_object())
      for (const auto& [k, v] : n.items()) walk(v, at + "." + k);
  };
  walk(j.at("inputs"), "");
  return found;
}

// What is wrong with a finished run, or "" when nothing is.
std::string judge(const ChildRun& run, const Mutant& m) {
  if (run.timed_out) return "hang: killed after " + std::to_string(run.seconds) + " s";
  if (run.signal) return "crash: signal " + std::to_string(run.signal);
  if (run.err.find("internal error") != std::string::npos) return "internal error";
  if (run.exit_code != 0 && run.exit_code != 2 && run.exit_code != 3 && run.exit_code != 4)
    return "exit code " + std::to_string(run.exit_code);
  const bool design = m.args[0] == "design";
  const fs::path output = run.folder / (design ? "o" : "m.json");
  if (run.exit_code != 0) {
    if (fs::exists(output)) return "output written on an error exit";
    if (run.err.size() > 2000) return "an error message of " + std::to_string(run.err.size()) + " bytes";
  }
  if (run.exit_code == 2) {
    static const char* const names[] = {"c.toml", "materials/", "--set", "--model", "built-in"};
    if (std::none_of(std::begin(names), std::end(names),
                     [&](const char* n) { return run.err.find(n) != std::string::npos; }))
      return "exit 2 names neither the file nor the option";
  }
  if (run.exit_code != 0 || !design) return "";
  nlohmann::json results;
  try {
    results = nlohmann::json::parse(slurp(output / "results.json"));
  } catch (const std::exception& e) {
    return std::string("results.json unreadable: ") + e.what();
  }
  if (auto bad = non_finite_in_results(results); !bad.empty()) return bad;
  // The results table and the verdict (the description above them echoes the case's own text).
  const std::string text = slurp(output / "results.txt");
  static const std::regex non_finite(R"(\b(inf|nan)\b)", std::regex::icase);
  if (std::regex_search(text.substr(std::min(text.find("\nResults\n"), text.size())), non_finite))
    return "inf or nan in results.txt";
  for (const auto& entry : fs::directory_iterator(output))
    if (entry.path().filename().string().find(".tmp") != std::string::npos) return "a temporary left behind";
  return "";
}

std::string describe(const Mutant& m, const ChildRun& run, std::uint64_t seed) {
  std::ostringstream s;
  s << "seed " << seed << ", mutant " << m.index << " of " << m.base << ": " << m.operation << "\n  feedflow";
  for (const auto& a : m.args) s << " '" << a.substr(0, 120) << (a.size() > 120 ? "...'" : "'");
  s << "\n  exit " << run.exit_code << " after " << run.seconds << " s; stderr: " << run.err.substr(0, 400)
    << "\n  c.toml (first 600 bytes):\n" << m.case_text.substr(0, 600);
  return s.str();
}

// Every mutant ends in a result or a named error, and writes only when it succeeds.
TEST(CaseFuzz, EveryMutantEndsInAResultOrANamedError) {
  const std::uint64_t seed = env_number("FEEDFLOW_FUZZ_SEED", kSeed);
  const std::size_t count = env_number("FEEDFLOW_FUZZ_MUTANTS", kMutants);
  const fs::path source = fs::path(FEEDFLOW_SOURCE_DIR) / "cases";
  std::vector<SourceFile> cases;
  for (const auto& entry : fs::directory_iterator(source))
    if (entry.path().extension() == ".toml") cases.push_back({entry.path().filename().string(), slurp(entry.path())});
  std::sort(cases.begin(), cases.end(), [](const auto& a, const auto& b) { return a.name < b.name; });
  ASSERT_GE(cases.size(), 4u);
  CaseMutator mutator(cases, {"loblolly_pine.toml", slurp(source / "materials/loblolly_pine.toml")}, seed);

  const fs::path root = scratch_folder("feedflow_fuzz", false);
  std::vector<Mutant> mutants;
  std::vector<ChildRun> runs;
  for (std::size_t i = 0; i < count; ++i) {
    mutants.push_back(mutator.next(i));
    ChildRun run;
    run.folder = root / std::to_string(i);
    run.args = mutants.back().args;
    write_mutant(run.folder, mutants.back());
    runs.push_back(std::move(run));
  }
  std::map<int, int> exits;
  std::size_t failures = 0;
  const auto start = std::chrono::steady_clock::now();
  const unsigned parallel = std::max(2u, std::thread::hardware_concurrency());
  run_children(FEEDFLOW_EXECUTABLE, runs, parallel, std::chrono::seconds(60), [&](ChildRun& run) {
    const Mutant& m = mutants[std::stoul(run.folder.filename().string())];
    ++exits[run.timed_out ? -2 : run.signal ? -1 : run.exit_code];
    const std::string problem = judge(run, m);
    if (!problem.empty() && ++failures <= 20) ADD_FAILURE() << problem << "\n" << describe(m, run, seed);
    if (problem.empty()) fs::remove_all(run.folder);
  });
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::cout << count << " mutants (seed " << seed << ") in " << wall << " s on " << parallel << " processes; exits:";
  for (const auto& [code, n] : exits) std::cout << " " << code << " x" << n;
  std::cout << "\n";
  EXPECT_EQ(failures, 0u);
  if (failures == 0) fs::remove_all(root);
}

}  // namespace
