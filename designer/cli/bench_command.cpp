// feedflow bench: run time against error for every rung and setting of the seed's design
// questions (designer/bench/), into bench.json, bench.csv and a report with one chart per
// question. Resumable: runs already in the output folder are read back, not run again.
#include <chrono>
#include <iostream>
#include <map>
#include <memory>
#include <set>
#include <algorithm>

#include "designer/bench/bench_plan.hpp"
#include "designer/bench/bench_run.hpp"
#include "designer/bench/bench_table.hpp"
#include "designer/bench/measured_bench.hpp"
#include "designer/case/case_loader.hpp"
#include "designer/case/shipped_cases.hpp"
#include "designer/cli/command_options.hpp"
#include "designer/cli/commands.hpp"
#include "designer/cli/exit_codes.hpp"
#include "designer/cli/invocation.hpp"
#include "designer/cli/output_files.hpp"
#include "designer/cli/output_folder.hpp"
#include "designer/cli/report_files.hpp"
#include "designer/verify/verified_bench_point.hpp"
#include "models/core/commit.hpp"
#include "models/core/errors.hpp"
#include "models/core/version.hpp"
#include "models/os/interrupt_request.hpp"
#include "models/units/quantity_format.hpp"
#include "models/units/quantity_parser.hpp"
#include "reports/results_json.hpp"

namespace feedflow {
namespace {

struct BenchArguments {
  bool quick = false;
  bool list = false;
  bool report = false;
  bool tabulate = false;           // make no runs: tabulate the ones in the output folder
  bool measured = false;           // show the shipped table
  std::string tolerance = "10%";   // what --measured picks the cheapest setting for
  std::vector<std::string> only;   // question ids
  std::vector<std::string> rungs;  // L0..L3; empty: all
  std::string finest_cell;         // CEL points on finer cells are not run; empty: all
  std::string matching;            // only points whose command holds this text; empty: all
  CommandOptions options;
};

std::vector<BenchQuestion> selected_questions(const BenchArguments& args) {
  std::vector<BenchQuestion> all = seed_bench_questions();
  if (args.only.empty()) return all;
  std::vector<BenchQuestion> chosen;
  for (const auto& id : args.only) {
    const auto it = std::find_if(all.begin(), all.end(), [&](const BenchQuestion& q) { return q.id == id; });
    if (it == all.end()) {
      std::string known;
      for (const auto& q : all) known += (known.empty() ? "" : ", ") + q.id;
      throw InputError("--only", id, "no bench question named '" + id + "'; known: " + known);
    }
    chosen.push_back(*it);
  }
  return chosen;
}

// [m] --finest-cell, or 0 when not given.
double finest_cell(const BenchArguments& args) {
  if (args.finest_cell.empty()) return 0.0;
  double h = 0.0;
  try {
    h = parse_quantity_as(args.finest_cell, dim::length, false);
  } catch (const std::invalid_argument& e) {
    throw InputError("--finest-cell", args.finest_cell,
                     std::string(e.what()) + "; expected a length, e.g. 5 mm");
  }
  if (!(h > 0.0))
    throw InputError("--finest-cell", args.finest_cell, "expected a positive length, e.g. 5 mm");
  return h;
}

// The point is of a chosen rung, its command (as --list shows it) holds --matching and, for a CEL
// point, it is on cells no finer than --finest-cell.
bool wanted_point(const BenchArguments& args, double finest, const BenchQuestion& q,
                  const BenchPoint& p) {
  if (finest > 0.0 && p.cell_size && *p.cell_size < finest * (1.0 - 1e-9)) return false;
  if (!args.matching.empty() && bench_invocation(q, p).find(args.matching) == std::string::npos)
    return false;
  return args.rungs.empty() || std::find(args.rungs.begin(), args.rungs.end(), p.rung) != args.rungs.end();
}

// The report's record: each question's reference as a result, its chart, and the notes.
DesignRecord bench_record(const std::vector<BenchQuestionTable>& tables, bool quick, double wall_seconds) {
  DesignRecord r;
  r.feedflow_version = kVersion;
  r.case_name = "bench";
  r.description = std::string("feedflow bench") + (quick ? " --quick" : "") + ": run time against error, " +
                  std::to_string(tables.size()) + " design questions of the seed's scenes";
  for (const auto& t : tables) {
    const BenchReference& ref = t.reference;
    if (ref.source.empty()) {
      r.assumptions.push_back(t.question->id + ": no reference (its reference runs were not made)");
      continue;
    }
    Estimate e;
    if (t.question->categorical) e.value = ref.label;
    else {
      e.value = *ref.value;
      e.unit = ref.unit;
      if (ref.error_bar) {
        e.low = *ref.value - *ref.error_bar;
        e.high = *ref.value + *ref.error_bar;
      }
    }
    e.model = ref.source;
    e.rung = Rung::L2;
    r.results.emplace_back(t.question->id, e);
    if (auto chart = error_against_time_chart(t)) r.charts.push_back(std::move(*chart));
    if (!ref.agreement.empty()) r.assumptions.push_back(t.question->id + ": " + ref.agreement);
  }
  r.assumptions.push_back("errors are relative to the reference; labels are right or wrong; the tables are in "
                          "bench.csv and bench.json");
  r.verdict.reasons.push_back("note: a benchmark, not a design check");
  r.command_line = invocation();
  r.wall_seconds = wall_seconds;
  return r;
}

// Each question's case file loads with the question's settings: a missing or broken one is bad
// input, refused before any run is made or read back (a run that failed on it would replace the
// run saved in its folder).
void check_case_files(const std::vector<BenchQuestion>& questions,
                      const std::filesystem::path& root) {
  for (const auto& q : questions) {
    std::vector<SetOverride> overrides;
    for (const auto& set : q.sets) overrides.push_back(parse_set_override(set));
    load_case((root / q.case_file).string(), overrides);
  }
}

void list_bench(const std::vector<BenchQuestion>& questions, const std::string& matching) {
  for (const auto& q : questions) {
    std::cout << q.id << ": " << q.title << '\n';
    for (const auto& p : q.points)
      if (bench_invocation(q, p).find(matching) != std::string::npos)
        std::cout << "  " << (p.quick ? "quick " : "full  ") << p.rung << "  "
                  << bench_invocation(q, p) << '\n';
  }
}

struct BenchRuns {
  std::map<std::filesystem::path, BenchRun> by_folder;
  std::size_t made = 0, read_back = 0;
  bool interrupted = false;
};

// Each selected run once (the drum's angle and regime share theirs), read back when a run.json
// of the same invocation is in its folder; stops at Ctrl-C.
BenchRuns make_runs(const BenchArguments& args, double finest,
                    const std::vector<BenchQuestion>& questions,
                    const std::filesystem::path& cases_root,
                    const std::filesystem::path& runs_root) {
  std::vector<std::pair<const BenchQuestion*, const BenchPoint*>> todo;
  std::set<std::filesystem::path> seen;
  for (const auto& q : questions)
    for (const auto& p : q.points)
      if ((!args.quick || p.quick) && wanted_point(args, finest, q, p) &&
          seen.insert(bench_run_folder(runs_root, q, p)).second)
        todo.emplace_back(&q, &p);
  BenchRuns runs;
  const bool say = args.options.human_output();
  for (std::size_t k = 0; k < todo.size(); ++k) {
    const auto& [q, p] = todo[k];
    const std::filesystem::path dir = bench_run_folder(runs_root, *q, *p);
    const bool announced = say && !args.tabulate && !saved_run_of(*q, *p, cases_root, dir);
    if (announced)
      std::cout << "[" << k + 1 << "/" << todo.size() << "] " << q->id << ": " << p->rung << " "
                << p->setting
                << (interrupted_bench_run(dir, bench_invocation(*q, *p),
                                          bench_inputs_fingerprint(*q, *p, cases_root))
                        ? " (continued from its checkpoint)"
                        : "")
                << " ..." << std::flush;
    if (args.tabulate) {
      if (auto saved = saved_run_of(*q, *p, cases_root, dir)) {
        runs.by_folder[dir] = std::move(*saved);
        ++runs.read_back;
      }
      continue;
    }
    bool made = false;
    BenchRun run = run_or_read_back_any(*q, *p, cases_root, dir, made);
    if (!made) {  // a verified point may be made again from its kept runs alone
      if (announced) std::cout << " read back\n";
      runs.by_folder[dir] = std::move(run);
      ++runs.read_back;
      continue;
    }
    if (say) std::cout << " " << format_number(run.wall_seconds, 3) << " s" << (run.done() ? "" : " (" + run.status + ")") << '\n';
    if (run.status == "interrupted" || interrupt_requested()) {
      runs.interrupted = true;
      return runs;
    }
    runs.by_folder[dir] = std::move(run);
    ++runs.made;
  }
  return runs;
}

std::string reference_line(const BenchQuestionTable& t) {
  const BenchReference& r = t.reference;
  if (r.source.empty()) return t.question->id + ": reference none";
  const std::string value =
      t.question->categorical ? r.label
      : r.error_bar           ? format_number(*r.value, 4) + " +- " + format_number(*r.error_bar, 3) + " " + r.unit
                              : format_number(*r.value, 4) + " " + r.unit;
  return t.question->id + ": reference " + value + " (" + r.source + ")";
}

// The shipped table: per question its reference and the cheapest measured setting whose error
// is within the tolerance.
int show_measured(const BenchArguments& args) {
  double tolerance = 0.0;
  try {
    tolerance = parse_quantity_as(args.tolerance, dim::dimensionless);
  } catch (const std::invalid_argument& e) {
    throw InputError("--tolerance", args.tolerance, std::string(e.what()) + "; expected a fraction, e.g. 10%");
  }
  if (!(tolerance > 0.0)) throw InputError("--tolerance", args.tolerance, "expected a positive fraction, e.g. 10%");
  const MeasuredBench& table = measured_bench();
  nlohmann::ordered_json j;
  j["measured"] = {{"date", table.date}, {"provenance", table.provenance}};
  j["tolerance"] = tolerance;
  j["questions"] = nlohmann::ordered_json::array();
  const bool say = args.options.human_output();
  if (say)  // the machine in a few words; every point set's commit and load in the JSON
    std::cout << "Bench table shipped with feedflow, measured " << table.date << " on "
              << table.provenance.substr(0, table.provenance.find(". "))
              << " (each point set's commit and load: --json -).\nCheapest measured setting within "
              << format_number(100 * tolerance, 3) << " % of the reference:\n";
  for (const auto& q : table.questions) {
    const MeasuredAnswer* best = cheapest_within(q, tolerance);
    nlohmann::ordered_json jq{{"id", q.id}, {"reference_source", q.reference_source}};
    std::string reference = "none";
    if (q.reference) {
      reference = format_number(*q.reference, 4) + (q.error_bar ? " +- " + format_number(*q.error_bar, 3) : "") + " " + q.unit;
      jq["reference"] = *q.reference;
      jq["unit"] = q.unit;
    } else if (!q.reference_label.empty()) {
      reference = q.reference_label;
      jq["reference"] = q.reference_label;
    }
    if (best)
      jq["cheapest"] = {{"rung", best->rung}, {"setting", best->setting}, {"error", *best->error},
                        {"wall_seconds", *best->wall_seconds}, {"invocation", best->invocation}};
    j["questions"].push_back(jq);
    if (!say) continue;
    std::cout << "  " << q.id << ": reference " << reference;
    if (!q.reference_source.empty()) std::cout << " (" << q.reference_source << ")";
    std::cout << "\n    ";
    if (!q.reference && q.reference_label.empty()) std::cout << "no reference measured: nothing can be chosen\n";
    else if (!reference_resolves(q, tolerance))
      std::cout << "the reference's own error bar (" << format_number(100 * *q.error_bar / std::abs(*q.reference), 3)
                << " %) is wider than the tolerance: nothing can be chosen\n";
    else if (!best) std::cout << "no measured setting is within the tolerance\n";
    else
      std::cout << best->rung << " " << best->setting << ": error " << format_number(100 * *best->error, 3) << " %, "
                << format_quantity(*best->wall_seconds, "s", 3) << "\n";
  }
  write_json_copy(j.dump(2) + "\n", args.options);
  return kExitOk;
}

int run_bench(const BenchArguments& args) {
  const auto start = std::chrono::steady_clock::now();
  if (args.measured) return show_measured(args);
  const std::vector<BenchQuestion> questions = selected_questions(args);
  const double finest = finest_cell(args);
  if (args.list) {
    list_bench(questions, args.matching);
    return kExitOk;
  }
  const std::filesystem::path cases_root = shipped_case_root();
  check_case_files(questions, cases_root);
  const std::filesystem::path out = args.options.out.empty() ? std::string("out/bench") : args.options.out;
  OutputFolder folder(out, "--out");
  install_interrupt_handler();
  const BenchRuns runs = make_runs(args, finest, questions, cases_root, out / "runs");

  std::vector<BenchQuestionTable> tables;
  std::vector<std::map<std::string, BenchRun>> by_question(questions.size());
  for (std::size_t i = 0; i < questions.size(); ++i) {
    for (const auto& p : questions[i].points) {
      const auto it = runs.by_folder.find(bench_run_folder(out / "runs", questions[i], p));
      if (it != runs.by_folder.end()) by_question[i][point_id(p)] = it->second;
    }
    tables.push_back(tabulate(questions[i], by_question[i]));
  }
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  nlohmann::ordered_json json;
  json["feedflow_bench"] = args.quick ? "quick" : "full";
  json["command_line"] = invocation();
  json["commit"] = kCommit;
  json["runs_made"] = runs.made;
  json["runs_read_back"] = runs.read_back;
  json["wall_seconds"] = wall;
  json["questions"] = bench_json(tables);
  const std::string json_text = json.dump(2) + "\n";
  std::vector<OutputFile> files = {{out / "bench.json", json_text, "--out"}, {out / "bench.csv", bench_csv(tables), "--out"}};
  if (args.report)
    for (auto& f : report_files(out, bench_record(tables, args.quick, wall))) files.push_back(std::move(f));
  if (!args.options.json.empty() && !args.options.json_to_stdout())
    files.push_back({args.options.json, json_text, "--json"});
  const auto written = write_outputs(files, args.options.json_to_stdout() ? &json_text : nullptr,
                                     args.options.verbose, &folder);
  if (args.options.human_output()) {
    for (const auto& t : tables) {
      std::cout << reference_line(t) << '\n';
      if (!t.reference.agreement.empty()) std::cout << "  " << t.reference.agreement << '\n';
    }
    std::cout << runs.made << " run(s) made, " << runs.read_back << " read back, " << format_number(wall, 3) << " s\nWritten: ";
    for (std::size_t i = 0; i < written.size(); ++i) std::cout << (i ? ", " : "") << written[i].string();
    std::cout << '\n';
  }
  if (runs.interrupted) {
    std::cerr << continue_after_interrupt(out / "runs");
    return kExitInterrupted;
  }
  return kExitOk;
}

}  // namespace

void add_bench_command(Command& program, int& exit_code) {
  auto args = std::make_shared<BenchArguments>();
  auto command = program.subcommand(
      "bench", "run time against error for every rung and setting of the seed's design questions");
  command.flag("--quick", args->quick, "coarse points only (minutes); the full bench takes hours");
  command.flag("--list", args->list, "list the questions and the runs of each, then stop");
  command.flag("--report", args->report,
               "also write report.pdf and report.html (one chart per question)");
  command.flag("--tabulate", args->tabulate,
               "make no runs: tabulate the runs already in the output folder");
  command.flag(
      "--measured", args->measured,
      "show the bench table shipped with feedflow: each question's reference and the cheapest "
      "measured setting within --tolerance");
  command
      .option("--tolerance", args->tolerance, "error allowed against the reference, for --measured")
      .show_default()
      .type_name("FRACTION");
  command.option("--only", args->only, "question ids to run (default: all; see --list)")
      .delimiter(',')
      .type_name("ID[,ID...]");
  command
      .option("--rungs", args->rungs,
              "rungs to run (default: all), e.g. L0,L1 for the reduced models")
      .delimiter(',')
      .one_of({"L0", "L1", "L2", "L3"})
      .type_name("RUNG[,RUNG...]");
  command
      .option(
          "--finest-cell", args->finest_cell,
          "CEL points on cells finer than this are not run (each halving costs about 8x), e.g. 5mm")
      .type_name("LENGTH");
  command
      .option("--matching", args->matching,
              "only the points whose command (as --list shows it) holds this text, e.g. "
              "\"verify dem\" for the particle rung's bisections")
      .type_name("TEXT");
  command
      .option("--out", args->options.out,
              "output folder (default out/bench); runs already in it are read back, not run again")
      .type_name("DIR");
  add_json_option(command, args->options, "the bench JSON");
  add_verbosity_options(command, args->options, true);
  command.on_run([args, &exit_code] { exit_code = run_bench(*args); });
}

}  // namespace feedflow
