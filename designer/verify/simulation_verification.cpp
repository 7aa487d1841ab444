#include "designer/verify/simulation_verification.hpp"

#include <algorithm>
#include <ostream>

#include "designer/verify/rejudge.hpp"
#include "models/units/quantity_format.hpp"
#include "models/units/quantity_parser.hpp"
#include "reports/result_format.hpp"
#include "reports/results_json.hpp"

namespace feedflow {
namespace {

const char* rung_name(Solver s) {
  return s == Solver::dem ? "particle rung (DEM)" : "continuum rung (CEL-FEM)";
}

// The answer as people read it: "41.3 deg (band 38.1 .. 44.6 deg)", "rolling".
std::string answer(const Estimate& e) {
  if (!e.is_number()) return std::get<std::string>(e.value);
  return estimate_value_text(e) +
         (e.low && e.high ? " (band " + estimate_band_text(e) + ")" : std::string());
}

// Whether the reduced band meets the simulated answer's: its band, or for a time average with
// an interval of its mean (`interval`, a half-width), that interval (the band of a fluctuating
// answer says where one snapshot lies, not where the mean does).
bool agree(const Estimate& reduced, const Estimate& simulated, const Estimate* interval) {
  if (reduced.is_number() != simulated.is_number()) return false;
  if (!reduced.is_number())
    return std::get<std::string>(reduced.value) == std::get<std::string>(simulated.value);
  const double r = std::get<double>(reduced.value), s = std::get<double>(simulated.value);
  double low = simulated.low.value_or(s), high = simulated.high.value_or(s);
  if (interval && interval->is_number() && interval->unit == simulated.unit) {
    low = s - std::get<double>(interval->value);
    high = s + std::get<double>(interval->value);
  }
  return reduced.low.value_or(r) <= high && low <= reduced.high.value_or(r);
}

// ", its mean's 95 % interval +-1.1 deg" for an answer that has one.
std::string interval_text(const Estimate* interval) {
  if (!interval || !interval->is_number()) return "";
  return ", its mean's 95 % interval +-" + estimate_value_text(*interval);
}

// The thinnest layer the run resolves [m]: two particle diameters (DEM) or two cells (CEL, when the
// case sets the cell size); 0 when unknown.
double thinnest_resolved(const Case& c, Solver solver) {
  if (solver == Solver::dem) return c.material.dem ? 4.0 * c.material.dem->particle.radius : 0.0;
  return c.cel.cell_size ? 2.0 * *c.cel.cell_size : 0.0;
}

// A layer thickness of a chute the run cannot resolve: why, or "" when it can.
std::string unresolved(const Case& c, Solver solver, const std::string& key, const Estimate& e) {
  const double floor = thinnest_resolved(c, solver);
  if (c.kind() != EquipmentKind::chute || !e.is_number() || floor <= 0.0 ||
      key.find("thickness") == std::string::npos)
    return "";
  double metres = std::get<double>(e.value);
  try {
    metres *= parse_unit(e.unit).si;
  } catch (const UnitError&) {
    return "";
  }
  if (metres >= floor) return "";
  return quantity_label(key) + " not verified on the " + rung_name(solver) + ": its " +
         estimate_value_text(e) + " is thinner than " +
         (solver == Solver::dem ? "two particle diameters" : "two cells") + " (" +
         format_quantity(floor, "mm", 3) +
         "), which the run cannot resolve; the reduced answer stands";
}

}  // namespace

SimulationVerification verify_by_simulation(const std::string& case_file,
                                            const std::vector<std::string>& sets, Solver solver,
                                            const std::filesystem::path& runs_folder,
                                            std::ostream* progress) {
  BenchQuestion q;
  q.id = "verify_simulation";
  q.case_file = case_file;
  q.sets = sets;
  BenchPoint p;
  p.setting = solver == Solver::dem ? "DEM" : "CEL";
  p.rung = solver == Solver::dem ? "L3" : "L2";
  p.solver = solver;
  SimulationVerification v;
  v.solver = solver;
  v.folder = bench_run_folder(runs_folder, q, p);
  if (progress) *progress << "verify: " << bench_invocation(q, p) << " ..." << std::flush;
  v.run = run_or_read_back(q, p, ".", v.folder, v.made);
  if (progress)
    *progress << ' '
              << (v.made ? format_number(v.run.wall_seconds, 3) + " s" : std::string("read back"))
              << '\n';
  return v;
}

void apply_simulation_verification(const Case& c, const SimulationVerification& v,
                                   DesignRecord& record) {
  const std::string rung = rung_name(v.solver);
  if (!v.run.done()) {
    record.verdict.reasons.push_back("not verified on the " + rung + ": " + v.run.status);
    return;
  }
  const Estimates simulated = estimates_from_json(v.run.results);
  std::vector<std::string> notes;
  for (const auto& [key, estimate] : simulated) {
    const Estimate* beside = find_estimate(simulated, reduced_model_key(key));
    const auto it = std::find_if(record.results.begin(), record.results.end(),
                                 [&](const auto& r) { return r.first == key; });
    if (!beside || it == record.results.end()) continue;
    if (const std::string why = unresolved(c, v.solver, key, estimate); !why.empty()) {
      notes.push_back(why);
      continue;
    }
    const Estimate reduced = it->second;
    Estimate full = estimate;
    if (full.display_unit.empty()) full.display_unit = reduced.display_unit;
    it->second = full;
    record.results.emplace(it + 1, reduced_model_key(key), reduced);
    const Estimate* interval = find_estimate(simulated, interval_key(key));
    notes.push_back(quantity_label(key) +
                    (agree(reduced, full, interval) ? " verified" : " contradicted") + " on the " +
                    rung + ": reduced " + answer(reduced) + ", " +
                    (v.solver == Solver::dem ? "DEM " : "CEL ") + answer(full) +
                    interval_text(interval) + " (" + full.model + ")");
  }
  if (notes.empty())
    notes.push_back("the " + rung + " run gave nothing to compare with the reduced answers");
  rejudge(c, record);
  const std::string runs =
      v.made ? format_number(v.run.wall_seconds, 3) + " s of runs" : "read back";
  for (auto& n : notes) record.verdict.reasons.push_back(n + "; " + runs);
}

}  // namespace feedflow
