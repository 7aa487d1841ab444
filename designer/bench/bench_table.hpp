#pragma once
// The bench's answers to one question: its reference (the CEL refinement series extrapolated by
// Richardson, or the DEM run at the seed's resolution; where both exist, whether they agree),
// and each point's answer with its wall time, cores, error against the reference, whether its
// band holds the reference, and whether it is on the Pareto front of wall time against error.
// Numbers err relatively (|answer - reference| / |reference|); labels (arching, regime) are
// right (0) or wrong (1). A time-averaged answer carries its statistical interval: a CEL
// reference's error bar adds the finest level's in quadrature, a DEM reference's is its own.
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "designer/bench/bench_plan.hpp"
#include "designer/bench/bench_run.hpp"
#include "models/core/chart.hpp"

namespace feedflow {

struct BenchReference {
  std::string source;                // "CEL Richardson (20, 10, 5 mm; observed order 1.31)"; empty: none
  std::optional<double> value;       // numbers
  std::optional<double> error_bar;   // [unit] half-width
  std::optional<double> order;       // the CEL series' observed order of convergence
  std::string label;                 // labels
  std::string unit;
  std::string agreement;             // what the CEL and DEM references say of each other
  std::string only_run;              // point_id of the one run that is the reference (no error of its own)
};

struct BenchAnswer {
  const BenchPoint* point = nullptr;
  const BenchRun* run = nullptr;     // none: not run (not in this bench's selection)
  std::optional<double> value, low, high;
  // The half-width of the value's statistical 95 % interval (a time average's mean).
  std::optional<double> interval;
  std::string label;                 // a label answer, or why there is no answer
  std::string unit;
  std::optional<double> error;       // relative (numbers) or 0/1 (labels); none without reference
  std::optional<bool> band_holds_reference;
  bool pareto = false;
  // Whether the run ended at rest, for a point that asks (BenchPoint::rest_key); false: the value
  // is an upper bound, out of the reference and the ranking.
  std::optional<bool> at_rest;
};

struct BenchQuestionTable {
  const BenchQuestion* question = nullptr;
  BenchReference reference;
  std::vector<BenchAnswer> answers;  // one per point, in the plan's order
};

// `runs`: by point_id, the runs made or read back (points missing were not run).
BenchQuestionTable tabulate(const BenchQuestion& question, const std::map<std::string, BenchRun>& runs);

// bench.json: per question its reference and answers; bench.csv: one row per answer.
nlohmann::ordered_json bench_json(const std::vector<BenchQuestionTable>& tables);
std::string bench_csv(const std::vector<BenchQuestionTable>& tables);
// Error against wall time (log-log), one series per rung and the Pareto front; none for a
// question without a numeric reference.
std::optional<Chart> error_against_time_chart(const BenchQuestionTable& table);

}  // namespace feedflow
