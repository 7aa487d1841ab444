#pragma once
// The bench table measured with `feedflow bench` and shipped with the program
// (measured_bench.json, compiled in; its `measured` block says on which commits, machine and
// date): per design question the reference and each rung and setting's answer, error and wall
// time. What the designer reads to choose the cheapest setting that meets a tolerance, and what
// `feedflow calibrate` takes the CEL hopper's order of convergence from.
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace feedflow {

struct MeasuredAnswer {
  std::string rung;                   // "L0".."L3"
  std::string setting;                // "CEL cells 5mm", "hopper.discharge=beverloo"
  std::string resolution;             // "6 cells across the half outlet" (CEL points)
  std::string status;                 // "done", "not run", "failed: ..."
  std::string invocation;             // the command that measured it
  std::optional<double> value;        // numbers, in the question's unit
  std::string label;                  // labels
  std::optional<double> error;        // relative (numbers) or 0/1 (labels)
  std::optional<double> wall_seconds;
  int cores = 0;
  bool in_reference = false;          // one of the runs that make the reference
  bool at_rest = true;                // false: ended still flowing, its value an upper bound
};

struct MeasuredQuestion {
  std::string id, title, unit;
  bool categorical = false;
  std::optional<double> reference, error_bar, order;  // order: the CEL series' observed order
  std::string reference_label, reference_source;
  std::vector<MeasuredAnswer> answers;
};

struct MeasuredBench {
  std::string date;        // of the measurement
  std::string provenance;  // commits and machine, in words
  std::vector<MeasuredQuestion> questions;
  const MeasuredQuestion* find(std::string_view id) const;
};

// The table shipped with the program.
const MeasuredBench& measured_bench();
// Parses a bench table (bench.json with its `measured` block); throws std::invalid_argument.
MeasuredBench parse_measured_bench(std::string_view json);

// Whether the reference is sure enough to judge errors of `tolerance`: a label, or a number
// whose error bar is at most that fraction of it.
bool reference_resolves(const MeasuredQuestion& question, double tolerance);

// The measured answer of least wall time whose error is at most `tolerance` (relative; a label
// must be right) and that is not itself the reference; none when no measured setting meets it
// or the reference does not resolve the tolerance.
const MeasuredAnswer* cheapest_within(const MeasuredQuestion& question, double tolerance);

// measured_bench.json's text (generated from measured_bench_text.cpp.in).
std::string_view measured_bench_text();

}  // namespace feedflow
