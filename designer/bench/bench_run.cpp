#include "designer/bench/bench_run.hpp"

#include <omp.h>

#include <chrono>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <sstream>

#include "designer/case/case_loader.hpp"
#include "designer/case/material_text.hpp"
#include "designer/design/design_check.hpp"
#include "designer/simulate/simulation.hpp"
#include "fullsim/common/scene_run.hpp"
#include "models/core/commit.hpp"
#include "models/core/errors.hpp"
#include "models/os/atomic_file.hpp"
#include "reports/results_json.hpp"

namespace feedflow {
namespace {

// FNV-1a, 64 bits, as 16 hex digits: a fingerprint stable across builds and machines.
std::string fnv1a_hex(const std::string& bytes) {
  std::uint64_t h = 1469598103934665603ull;
  for (unsigned char c : bytes) {
    h ^= c;
    h *= 1099511628211ull;
  }
  char text[17];
  std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(h));
  return text;
}

std::string seconds_text(double s) {
  std::ostringstream o;
  o << s << "s";
  return o.str();
}

}  // namespace

std::string bench_invocation(const BenchQuestion& q, const BenchPoint& p) {
  std::string s = (p.solver ? "simulate " : "design ") + q.case_file;
  if (p.solver) s += std::string(" --solver ") + to_string(*p.solver);
  for (const auto& set : q.sets) s += " --set " + set;
  for (const auto& set : p.sets) s += " --set " + set;
  for (const auto& model : p.models) s += " --model " + model;
  if (p.time) s += " --time " + seconds_text(*p.time);
  if (!p.verify.empty()) {
    s += " --verify " + p.verify;
    if (!p.width_tolerance.empty()) s += " --width-tolerance " + p.width_tolerance;
    if (!p.thickness_tolerance.empty()) s += " --thickness-tolerance " + p.thickness_tolerance;
    s += " --budget " + std::string(kUnlimitedVerificationBudget);
  }
  return s;
}

std::filesystem::path bench_run_folder(const std::filesystem::path& root, const BenchQuestion& q,
                                       const BenchPoint& p) {
  std::string name = std::filesystem::path(q.case_file).stem().string();
  for (const auto& set : q.sets) name += "__" + set;
  name += "__" + point_id(p);
  if (p.time) name += "__" + seconds_text(*p.time);
  return root / file_name_friendly(name);
}

std::string bench_inputs_fingerprint(const BenchQuestion& q, const BenchPoint& p, const std::filesystem::path& source_root) {
  try {
    std::vector<SetOverride> overrides;
    for (const auto& set : q.sets) overrides.push_back(parse_set_override(set));
    const std::filesystem::path case_file = source_root / q.case_file;
    const Case c = load_case(case_file.string(), overrides);
    std::ifstream in(case_file);
    std::ostringstream text;
    text << in.rdbuf() << '\0' << (p.solver ? without_calibration(material_text(c.material)) : material_text(c.material));
    return fnv1a_hex(text.str());
  } catch (const std::exception&) {
    return {};
  }
}

BenchRun run_bench_point(const BenchQuestion& q, const BenchPoint& p,
                         const std::filesystem::path& source_root,
                         const std::filesystem::path& folder,
                         const std::filesystem::path& restart) {
  BenchRun run;
  run.invocation = bench_invocation(q, p);
  run.commit = kCommit;
  run.inputs = bench_inputs_fingerprint(q, p, source_root);
  const auto start = std::chrono::steady_clock::now();
  try {
    if (!p.verify.empty())  // designer/verify/verified_bench_point runs these
      throw std::logic_error("a verified design check is not a single run");
    std::vector<SetOverride> overrides;
    for (const auto& set : q.sets) overrides.push_back(parse_set_override(set));
    for (const auto& set : p.sets) overrides.push_back(parse_set_override(set));
    const Case c = load_case((source_root / q.case_file).string(), overrides);
    DesignRecord record;
    if (p.solver) {
      std::filesystem::create_directories(folder);
      std::ofstream log(folder / "run.log", restart.empty() ? std::ios::trunc : std::ios::app);
      log << std::unitbuf;  // the run's phases as they come (a long run can be followed)
      if (!restart.empty()) log << "continued from the checkpoint " << restart.string() << '\n';
      SimulationRequest request{c, *p.solver, p.time, folder, restart, false, &log};
      const SimulationOutcome outcome = simulate(request);
      if (outcome.end == SimulationEnd::interrupted) run.status = "interrupted";
      record = outcome.record;
      run.cores = omp_get_max_threads();
    } else {
      record = design_check(c, ModelChoices::parse(p.models));
    }
    const auto saved = to_json(record);
    run.results = saved.at("results");
    run.verdict = saved.at("verdict");
  } catch (const std::exception& e) {  // a bench row says why a point failed; the bench goes on
    run.status = std::string("failed: ") + e.what();
  }
  run.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return run;
}

std::optional<BenchRun> saved_bench_run(const std::filesystem::path& folder, const std::string& invocation,
                                        const std::string& inputs, bool accept_unfingerprinted) {
  std::ifstream in(folder / "run.json");
  if (!in) return std::nullopt;
  try {
    const auto j = nlohmann::ordered_json::parse(in);
    if (j.at("invocation").get<std::string>() != invocation) return std::nullopt;
    const std::string saved_inputs = j.value("inputs", "");
    const bool answered = j.contains("results") && !j.at("results").is_null();
    if (saved_inputs.empty() ? !(accept_unfingerprinted && answered) : saved_inputs != inputs)
      return std::nullopt;
    if (j.at("status").get<std::string>() == "interrupted")
      return std::nullopt;  // to continue, not to read
    BenchRun run = bench_run_from_json(j);
    run.inputs = saved_inputs;
    return run;
  } catch (const std::exception&) {  // damaged: run it again
    return std::nullopt;
  }
}

nlohmann::ordered_json bench_run_json(const BenchRun& run) {
  nlohmann::ordered_json j;
  j["invocation"] = run.invocation;
  j["status"] = run.status;
  j["wall_seconds"] = run.wall_seconds;
  j["cores"] = run.cores;
  j["results"] = run.results;
  j["verdict"] = run.verdict;
  j["commit"] = run.commit;
  j["inputs"] = run.inputs;
  return j;
}

BenchRun bench_run_from_json(const nlohmann::ordered_json& j) {
  BenchRun run;
  run.invocation = j.at("invocation").get<std::string>();
  run.status = j.at("status").get<std::string>();
  run.wall_seconds = j.at("wall_seconds").get<double>();
  run.cores = j.at("cores").get<int>();
  run.results = j.at("results");
  run.verdict = j.value("verdict", nlohmann::ordered_json());
  run.commit = j.value("commit", "");
  run.inputs = j.value("inputs", "");
  return run;
}

void save_bench_run(const std::filesystem::path& folder, const BenchRun& run) {
  std::filesystem::create_directories(folder);
  write_file_atomically(folder / "run.json", bench_run_json(run).dump(2) + "\n");
}

std::optional<BenchRun> saved_run_of(const BenchQuestion& q, const BenchPoint& p, const std::filesystem::path& source_root,
                                     const std::filesystem::path& folder) {
  return saved_bench_run(folder, bench_invocation(q, p), bench_inputs_fingerprint(q, p, source_root), p.solver.has_value());
}

std::filesystem::path interrupted_checkpoint(const std::filesystem::path& folder) {
  return folder / "interrupted.h5";
}

std::string continue_after_interrupt(const std::filesystem::path& runs) {
  return "feedflow: interrupted; run the same command again to continue (runs made are kept in " +
         runs.string() + ", a run cut short continues from its checkpoint)\n";
}

std::optional<BenchRun> interrupted_bench_run(const std::filesystem::path& folder,
                                              const std::string& invocation,
                                              const std::string& inputs) {
  if (inputs.empty() || !std::filesystem::exists(interrupted_checkpoint(folder)))
    return std::nullopt;
  std::ifstream in(folder / "run.json");
  if (!in) return std::nullopt;
  try {
    BenchRun run = bench_run_from_json(nlohmann::ordered_json::parse(in));
    if (run.status != "interrupted" || run.invocation != invocation || run.inputs != inputs)
      return std::nullopt;
    return run;
  } catch (const std::exception&) {  // damaged: start again
    return std::nullopt;
  }
}

void adopt_checkpoint_of_killed_run(const std::filesystem::path& folder,
                                    const std::string& invocation, const std::string& inputs) {
  const std::filesystem::path written = scene_checkpoint_path(folder);
  if (!std::filesystem::exists(written)) return;
  std::ifstream in(folder / "run.json");
  if (!in) return;
  try {
    const BenchRun run = bench_run_from_json(nlohmann::ordered_json::parse(in));
    if (run.status != "interrupted" || run.invocation != invocation || run.inputs != inputs ||
        inputs.empty())
      return;
  } catch (const std::exception&) {  // damaged: the run starts again
    return;
  }
  std::filesystem::rename(written, interrupted_checkpoint(folder));
}

BenchRun run_or_read_back(const BenchQuestion& q, const BenchPoint& p, const std::filesystem::path& source_root,
                          const std::filesystem::path& folder, bool& made) {
  if (auto saved = saved_run_of(q, p, source_root, folder)) {
    made = false;
    return std::move(*saved);
  }
  made = true;
  const std::string invocation = bench_invocation(q, p),
                    inputs = bench_inputs_fingerprint(q, p, source_root);
  const std::filesystem::path kept = interrupted_checkpoint(folder),
                              written = scene_checkpoint_path(folder);
  adopt_checkpoint_of_killed_run(folder, invocation, inputs);
  const auto before = interrupted_bench_run(folder, invocation, inputs);
  if (!before) {  // a checkpoint left by another run must not pass for this one's
    std::filesystem::remove(kept);
    std::filesystem::remove(written);
  }
  if (p.solver) {  // marked cut short until it ends: a run killed outright is known as this one
    BenchRun marker = before.value_or(BenchRun{});
    marker.invocation = invocation;
    marker.inputs = inputs;
    marker.status = "interrupted";
    if (marker.commit.empty()) marker.commit = kCommit;
    save_bench_run(folder, marker);
  }
  BenchRun run =
      run_bench_point(q, p, source_root, folder, before ? kept : std::filesystem::path());
  if (before) {
    run.wall_seconds += before->wall_seconds;
    if (before->commit != run.commit) run.commit = before->commit + ", continued on " + run.commit;
  }
  if (run.status == "interrupted") {
    if (!std::filesystem::exists(written))
      return run;  // cut before its first checkpoint: nothing new to keep
    std::filesystem::rename(written, kept);
  } else {
    std::filesystem::remove(kept);
  }
  save_bench_run(folder, run);
  return run;
}

}  // namespace feedflow
