#include "designer/verify/verified_bench_point.hpp"

#include <omp.h>

#include <algorithm>
#include <fstream>
#include <vector>

#include "designer/case/case_loader.hpp"
#include "designer/design/design_check.hpp"
#include "designer/verify/design_verification.hpp"
#include "models/core/commit.hpp"
#include "reports/results_json.hpp"

namespace feedflow {
namespace {

std::size_t kept_run_count(const std::filesystem::path& runs) {
  std::error_code ec;
  std::size_t n = 0;
  for (const auto& entry : std::filesystem::directory_iterator(runs, ec))
    n += std::filesystem::exists(entry.path() / "run.json", ec) ? 1 : 0;
  return n;
}

// The runs a verification keeps below `runs`: their wall times added up, and their commits
// (each once, in the order met; a run's own may already name two).
void add_runs(const std::filesystem::path& runs, BenchRun& into) {
  std::vector<std::filesystem::path> folders;
  std::error_code ec;
  for (const auto& entry : std::filesystem::directory_iterator(runs, ec))
    folders.push_back(entry.path());
  std::sort(folders.begin(), folders.end());
  std::vector<std::string> commits;
  into.wall_seconds = 0.0;
  for (const auto& folder : folders) {
    std::ifstream in(folder / "run.json");
    if (!in) continue;
    try {
      const BenchRun run = bench_run_from_json(nlohmann::ordered_json::parse(in));
      into.wall_seconds += run.wall_seconds;
      if (!run.commit.empty() &&
          std::find(commits.begin(), commits.end(), run.commit) == commits.end())
        commits.push_back(run.commit);
    } catch (const std::exception&) {  // damaged: the verification made it again
    }
  }
  if (commits.empty()) return;
  into.commit.clear();
  for (const auto& commit : commits) into.commit += (into.commit.empty() ? "" : "; ") + commit;
}

}  // namespace

BenchRun run_or_read_back_verified(const BenchQuestion& q, const BenchPoint& p,
                                   const std::filesystem::path& source_root,
                                   const std::filesystem::path& folder, bool& made) {
  if (auto saved = saved_run_of(q, p, source_root, folder)) {
    made = false;
    return std::move(*saved);
  }
  // Made when the verification makes a run of its own, not when it reads them all back (say
  // after the material's calibration changed the point's inputs, not its runs').
  const std::size_t kept_before = kept_run_count(folder / "verify");
  BenchRun run;
  run.invocation = bench_invocation(q, p);
  run.commit = kCommit;
  run.inputs = bench_inputs_fingerprint(q, p, source_root);
  try {
    VerificationRequest request;
    request.case_file = (source_root / q.case_file).lexically_normal().string();
    request.sets = q.sets;
    request.sets.insert(request.sets.end(), p.sets.begin(), p.sets.end());
    std::vector<SetOverride> overrides;
    for (const auto& set : request.sets) overrides.push_back(parse_set_override(set));
    const Case c = load_case(request.case_file, overrides);
    DesignRecord record = design_check(c, ModelChoices::parse(p.models));
    std::filesystem::create_directories(folder);
    std::ofstream log(folder / "run.log", std::ios::app);
    log << std::unitbuf;  // the runs' plans and phases as they come
    request.mode = p.verify;
    request.budget = kUnlimitedVerificationBudget;
    if (!p.width_tolerance.empty()) request.width_tolerance = p.width_tolerance;
    request.thickness_tolerance = p.thickness_tolerance;
    request.runs = folder / "verify";
    request.log = &log;
    if (!verify_design(request, c, record)) run.status = "interrupted";
    run.cores = omp_get_max_threads();
    const auto saved = to_json(record);
    run.results = saved.at("results");
    run.verdict = saved.at("verdict");
  } catch (const std::exception& e) {  // a bench row says why a point failed; the bench goes on
    run.status = std::string("failed: ") + e.what();
  }
  add_runs(folder / "verify", run);
  made = kept_run_count(folder / "verify") > kept_before || run.status != "done";
  if (run.status != "interrupted") save_bench_run(folder, run);
  return run;
}

BenchRun run_or_read_back_any(const BenchQuestion& q, const BenchPoint& p,
                              const std::filesystem::path& source_root,
                              const std::filesystem::path& folder, bool& made) {
  return p.verify.empty() ? run_or_read_back(q, p, source_root, folder, made)
                          : run_or_read_back_verified(q, p, source_root, folder, made);
}

}  // namespace feedflow
